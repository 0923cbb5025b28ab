// The interfaces' checks of a cells request and the library's site errors
// moved to file lines (the library names sites by id).
#include "output/cell_request.hpp"
#include "util/error.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using namespace ellvor;

namespace {

SiteFile file_of(const std::string& text) {
    std::istringstream in(text);
    return read_site_file(in, "f.ell");
}

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const CellArgumentNames kNames = {"box", "periodic", "tolerance", "boundary_tolerance"};

}  // namespace

TEST_CASE("site_error_at_lines: one site or a pair, at the (later) site's line", "[output][cells]") {
    const SiteFile file = file_of("# header\n1 1 0 0 0\n\n1 1 0 5 0\n1 1 0 9 0\n");
    // One site (as the library names a site meeting its periodic image).
    const InputError one = site_error_at_lines(file, InputError("site 2 meets its own periodic image", InputError::SitePair{2, 2}));
    CHECK(std::string(one.what()) == "f.ell:5:1: site 2 meets its own periodic image");
    CHECK(one.line() == 5);
    REQUIRE(one.sites());
    CHECK(one.sites()->first == 2);
    // A pair, in either order.
    const InputError two = site_error_at_lines(file, InputError("sites 0 and 1 touch", InputError::SitePair{1, 0}));
    CHECK(std::string(two.what()) == "f.ell:4:1: sites 0 and 1 touch (site 0: line 2)");
    // Crossing sites: the readers' own message.
    const InputError crossing = site_error_at_lines(file, IntersectingSites(0, 2, "their boundaries meet in 4 points"));
    CHECK(std::string(crossing.what()) == "f.ell:5:1: site 2 crosses site 0 (line 2): their boundaries meet in 4 points");
    // No site, or no lines: unchanged.
    CHECK(std::string(site_error_at_lines(file, InputError("no site")).what()) == "no site");
    SiteFile bare = file;
    bare.lines.clear();
    CHECK(std::string(site_error_at_lines(bare, InputError("site 1", InputError::SitePair{1, 1})).what()) == "site 1");
}

TEST_CASE("check_cell_arguments and check_centers_in_box name the argument", "[output][cells]") {
    CellDomain box;
    box.kind = CellDomain::Kind::box;
    box.x0 = -1, box.y0 = -1, box.x1 = 6, box.y1 = 1;
    CHECK(message_of([&] { check_cell_arguments(box, 1e-9, std::nullopt, kNames); }).empty());
    CHECK(message_of([&] { check_cell_arguments(box, 0, std::nullopt, kNames); }) ==
          "tolerance: expected a number in (0, 1], got 0");
    CHECK(message_of([&] { check_cell_arguments(box, 1e-9, 0.0, kNames); }) ==
          "boundary_tolerance: expected a positive number, got 0");
    CellDomain flat = box;
    flat.kind = CellDomain::Kind::periodic;
    flat.y1 = Rational(-1);
    CHECK(message_of([&] { check_cell_arguments(flat, 1e-9, std::nullopt, kNames); }) ==
          "periodic: an empty box: Y0 = -1 is not below Y1 = -1");
    const SiteFile file = file_of("1 1 0 0 0\n1 1 0 6 1\n1 1 0 7 0\n");
    // The closed box holds a centre on its corner (6, 1); (7, 0) is outside.
    CHECK(message_of([&] { check_centers_in_box(file, box); }) ==
          "f.ell:3:1: site 2 has its center (7, 0) outside the box -1 -1 6 1");
    // The plane and the periodic box do not ask.
    CHECK(message_of([&] { check_centers_in_box(file, flat); }).empty());
}
