// libFuzzer target: arbitrary bytes read as a site file, in both formats.
//
// The reader must return a SiteFile (that survives its writer) or throw
// InputError; anything else, a crash or a sanitizer report is a finding
// (fuzz_checks.hpp says what is checked).
#include "fuzz/fuzz_checks.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (ellvor::SiteFormat format : {ellvor::SiteFormat::ell, ellvor::SiteFormat::cin}) {
        const ellvor::fuzz::Outcome outcome = ellvor::fuzz::read_site_text(text, format);
        if (outcome.kind == ellvor::fuzz::Outcome::finding) {
            std::fprintf(stderr, "fuzz_site_parser: %s\n", outcome.message.c_str());
            std::abort();
        }
    }
    return 0;
}
