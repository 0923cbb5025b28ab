#include "output/cell_request.hpp"

#include "util/error.hpp"

#include <cmath>
#include <sstream>

namespace ellvor {
namespace {

std::string number(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

std::string box_text(const CellDomain& d) {
    return d.x0.str() + " " + d.y0.str() + " " + d.x1.str() + " " + d.y1.str();
}

}  // namespace

void check_cell_arguments(const CellDomain& domain, double tolerance, std::optional<double> boundary_tolerance,
                          const CellArgumentNames& names) {
    if (!(tolerance > 0 && tolerance <= 1))
        throw InputError(names.tolerance + ": expected a number in (0, 1], got " + number(tolerance));
    if (boundary_tolerance && !(*boundary_tolerance > 0 && std::isfinite(*boundary_tolerance)))
        throw InputError(names.boundary_tolerance + ": expected a positive number, got " + number(*boundary_tolerance));
    if (domain.kind == CellDomain::Kind::plane) return;
    const std::string& name = domain.kind == CellDomain::Kind::box ? names.box : names.periodic;
    if (domain.x0 >= domain.x1)
        throw InputError(name + ": an empty box: X0 = " + domain.x0.str() + " is not below X1 = " + domain.x1.str());
    if (domain.y0 >= domain.y1)
        throw InputError(name + ": an empty box: Y0 = " + domain.y0.str() + " is not below Y1 = " + domain.y1.str());
}

void check_centers_in_box(const SiteFile& file, const CellDomain& domain) {
    if (domain.kind != CellDomain::Kind::box) return;
    for (std::size_t k = 0; k < file.sites.size(); ++k) {
        const Ellipse& e = file.sites[k];
        if (domain.x0 <= e.xc() && e.xc() <= domain.x1 && domain.y0 <= e.yc() && e.yc() <= domain.y1) continue;
        const std::string what = "site " + std::to_string(k) + " has its center (" + e.xc().str() + ", " +
                                 e.yc().str() + ") outside the box " + box_text(domain);
        if (k < file.lines.size()) throw InputError(file.name, file.lines[k], 1, what, InputError::SitePair{k, k});
        throw InputError(what, InputError::SitePair{k, k});
    }
}

InputError site_error_at_lines(const SiteFile& file, const InputError& error) {
    if (!error.sites() || error.has_location()) return error;
    auto [first, second] = *error.sites();
    if (first > second) std::swap(first, second);
    if (second >= file.lines.size()) return error;
    if (const auto* crossing = dynamic_cast<const IntersectingSites*>(&error))
        return crossing_sites_error(file, crossing->first(), crossing->second(), crossing->why());
    std::string what = error.reason();
    if (first != second) what += " (site " + std::to_string(first) + ": line " + std::to_string(file.lines[first]) + ")";
    return InputError(file.name, file.lines[second], 1, what, error.sites());
}

CellTessellation cells_of_site_file(const SiteFile& file, const CellDomain& domain, const CellOptions& options,
                                    std::optional<double> boundary_tolerance, const CellArgumentNames& names) {
    check_cell_arguments(domain, options.tolerance, boundary_tolerance, names);
    check_centers_in_box(file, domain);
    CellOptions o = options;
    o.boundary_tolerance = boundary_tolerance.value_or(0);
    try {
        return cell_tessellation(file.sites, domain, o);
    } catch (const InputError& e) {
        throw site_error_at_lines(file, e);
    }
}

}  // namespace ellvor
