#include "cli/site_arguments.hpp"

#include "predicates/relative_position.hpp"

namespace ellvor::cli {

SiteFile read_site_argument(const Arguments& parsed, const std::string& path) {
    return read_site_file(path, parsed.has("--cin") ? SiteFormat::cin : SiteFormat::ell);
}

void require_site_count(const SiteFile& file, std::size_t min, std::size_t max, const std::string& roles) {
    const std::size_t n = file.sites.size();
    if (n >= min && n <= max) return;
    const std::string expected = min == max ? "exactly " + std::to_string(min) : std::to_string(min) + " to " +
                                                                                  std::to_string(max);
    const std::string what = "expected " + expected + " sites (" + roles + "), found " + std::to_string(n);
    if (n > max) throw InputError(file.name, file.lines[max], 1, what);
    throw InputError(file.name + ": " + what);
}

void require_no_crossing(const SiteFile& file) {
    const auto& s = file.sites;
    for (std::size_t j = 1; j < s.size(); ++j)
        for (std::size_t i = 0; i < j; ++i)
            if (*relative_position(s[i], s[j]) == RelativePosition::intersecting) throw crossing_sites_error(file, i, j);
}

}  // namespace ellvor::cli
