#include "cli/site_arguments.hpp"

#include "predicates/relative_position.hpp"
#include "util/error.hpp"

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

void require_acceptable_crossings(const SiteFile& file) {
    try {
        ellvor::require_acceptable_crossings(file.sites);
    } catch (const IntersectingSites& e) {
        throw crossing_sites_error(file, e.first(), e.second(), e.why());
    }
}

}  // namespace ellvor::cli
