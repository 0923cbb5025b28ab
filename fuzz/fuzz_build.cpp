// libFuzzer target: small .ell files through what `ellvor build --validate` does,
// then its odd sites removed again (`build --remove`) and the graph checked again.
//
// An InputError (a parse error, a duplicate, intersecting sites) is fine; any
// other exception, an invalid graph, a crash, a hang or a sanitizer report is
// a finding (fuzz_checks.hpp says what is checked).
//
// Inputs are capped (bytes and sites) so that one execution stays fast: the
// fuzzer looks for wrong behaviour on few sites, not for slow large inputs.
#include "fuzz/fuzz_checks.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

constexpr std::size_t kMaxBytes = 512;
constexpr std::size_t kMaxFuzzSites = 8;

[[noreturn]] void report(const ellvor::fuzz::Outcome& finding) {
    std::fprintf(stderr, "fuzz_build: %s\n", finding.message.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using ellvor::fuzz::Outcome;
    if (size > kMaxBytes) return -1;  // -1: never added to the corpus
    const Outcome read = ellvor::fuzz::read_ell_text(std::string(reinterpret_cast<const char*>(data), size));
    if (read.kind == Outcome::finding) report(read);
    if (read.kind == Outcome::input_error) return 0;
    if (read.file.sites.size() > kMaxFuzzSites) return -1;
    const Outcome built = ellvor::fuzz::build_sites(read.file);
    if (built.kind == Outcome::finding) report(built);
    return 0;
}
