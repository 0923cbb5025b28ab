// Diagram.cells(): the certified cells as NumPy arrays, JSON and GeoJSON
// (python/ellvor/_cells.py wraps them). The checks and messages are those of
// `ellvor cells` (output/cell_request.hpp), with the arguments named as
// Python spells them.
#include "python/src/bindings.hpp"

#include "cells/box_mirrors.hpp"
#include "cells/cell_tessellation.hpp"
#include "output/cell_request.hpp"
#include "output/cells_geojson.hpp"
#include "output/cells_json.hpp"
#include "output/outward_decimal.hpp"
#include "output/packing_fraction.hpp"

#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>

namespace ellvor::python {
namespace {

const CellArgumentNames kNames = {"box", "periodic", "tolerance", "boundary_tolerance"};

struct Cells {
    CellTessellation t;
};

CellDomain domain_argument(py::handle box, py::handle periodic) {
    CellDomain d;
    if (!box.is_none() && !periodic.is_none()) throw InputError("box and periodic exclude each other");
    if (box.is_none() && periodic.is_none()) return d;
    const bool is_box = !box.is_none();
    const char* name = is_box ? "box" : "periodic";
    py::handle given = is_box ? box : periodic;
    std::vector<py::object> v;
    if (py::isinstance<py::iterable>(given) && !py::isinstance<py::str>(given))
        for (py::handle x : given) v.push_back(py::reinterpret_borrow<py::object>(x));
    if (v.size() != 4) throw InputError(std::string(name) + ": expected four numbers (x0, y0, x1, y1)");
    d.kind = is_box ? CellDomain::Kind::box : CellDomain::Kind::periodic;
    const std::string n = name;
    d.x0 = to_rational(v[0], n + "[0]");
    d.y0 = to_rational(v[1], n + "[1]");
    d.x1 = to_rational(v[2], n + "[2]");
    d.y1 = to_rational(v[3], n + "[3]");
    return d;
}

std::unique_ptr<Cells> cells(py::handle sites, py::handle box, py::handle periodic, double tolerance,
                             std::optional<double> boundary_tolerance, bool rings, std::vector<SiteId> only,
                             unsigned threads) {
    const Sites input = sites_argument(sites, "ell");
    const CellDomain domain = domain_argument(box, periodic);
    CellOptions options;
    options.tolerance = tolerance;
    options.rings = rings;
    options.only = std::move(only);
    options.threads = threads;
    auto out = std::make_unique<Cells>();
    py::gil_scoped_release release;
    out->t = cells_of_site_file(input.file, domain, options, boundary_tolerance, kNames);
    return out;
}

// The checks `cells` makes before any diagram (arguments, centers in a box,
// sites inside it), for the tiled cells to reject bad input on the client.
// Returns the box or periodic box as Fractions (x0, y0, x1, y1), None in the plane.
py::object check_cells(py::handle sites, py::handle box, py::handle periodic, double tolerance,
                       std::optional<double> boundary_tolerance) {
    const Sites input = sites_argument(sites, "ell");
    const CellDomain domain = domain_argument(box, periodic);
    check_cell_arguments(domain, tolerance, boundary_tolerance, kNames);
    check_centers_in_box(input.file, domain);
    if (domain.kind == CellDomain::Kind::plane) return py::none();
    if (domain.kind == CellDomain::Kind::box) {
        try {
            require_sites_inside_box(input.file.sites, domain);
        } catch (const InputError& e) {
            throw site_error_at_lines(input.file, e);
        }
    }
    return py::make_tuple(to_fraction(domain.x0), to_fraction(domain.y0), to_fraction(domain.x1), to_fraction(domain.y1));
}

// Per cell a ball's outward bounds into lo[k], hi[k].
template <class Get>
std::pair<py::array_t<double>, py::array_t<double>> bounds_arrays(const CellTessellation& t, Get get) {
    const auto n = static_cast<py::ssize_t>(t.cells.size());
    auto lo = new_array<double>({n}), hi = new_array<double>({n});
    auto l = lo.mutable_unchecked<1>();
    auto h = hi.mutable_unchecked<1>();
    for (py::ssize_t k = 0; k < n; ++k) std::tie(l(k), h(k)) = get(t.cells[static_cast<std::size_t>(k)]);
    return {lo, hi};
}

template <std::size_t N>
std::pair<py::array_t<double>, py::array_t<double>> ball_columns(const std::vector<Cell>& cells,
                                                                 std::array<Ball, N> Cell::*member) {
    const auto n = static_cast<py::ssize_t>(cells.size());
    auto lo = new_array<double>({n, static_cast<py::ssize_t>(N)}), hi = new_array<double>({n, static_cast<py::ssize_t>(N)});
    auto l = lo.mutable_unchecked<2>();
    auto h = hi.mutable_unchecked<2>();
    for (py::ssize_t k = 0; k < n; ++k)
        for (std::size_t i = 0; i < N; ++i)
            std::tie(l(k, static_cast<py::ssize_t>(i)), h(k, static_cast<py::ssize_t>(i))) =
                double_bounds((cells[static_cast<std::size_t>(k)].*member)[i]);
    return {lo, hi};
}

py::dict arrays(const Cells& c) {
    const CellTessellation& t = c.t;
    const auto n = static_cast<py::ssize_t>(t.cells.size());
    py::dict out;
    auto put = [&](const char* name, const std::pair<py::array_t<double>, py::array_t<double>>& b) {
        out[(std::string(name) + "_lo").c_str()] = b.first;
        out[(std::string(name) + "_hi").c_str()] = b.second;
    };
    put("area", bounds_arrays(t, [](const Cell& x) { return double_bounds(x.area); }));
    put("site_area", bounds_arrays(t, [](const Cell& x) { return double_bounds(x.site_area); }));
    put("perimeter", bounds_arrays(t, [](const Cell& x) { return double_bounds(x.perimeter); }));
    put("packing_fraction", bounds_arrays(t, [](const Cell& x) {
            const std::optional<Ball> f = packing_fraction(x);
            const double nan = std::numeric_limits<double>::quiet_NaN();
            return f ? double_bounds(*f) : std::pair<double, double>{nan, nan};
        }));
    put("centroid", ball_columns(t.cells, &Cell::centroid));
    put("second_moments", ball_columns(t.cells, &Cell::second_moments));
    auto site_area = new_array<double>({n});
    auto visible = new_array<bool>({n}), bounded = new_array<bool>({n});
    auto precision = new_array<std::int64_t>({n}), indptr = new_array<std::int64_t>({n + 1});
    auto reach = new_array<double>({n});
    std::size_t sides = 0;
    for (const Cell& x : t.cells) sides += x.sides.size();
    const auto m = static_cast<py::ssize_t>(sides);
    auto indices = new_array<std::int64_t>({m});
    auto shifts = new_array<std::int64_t>({m, 2}), side_vertices = new_array<std::int64_t>({m, 2});
    auto ind = indices.mutable_unchecked<1>();
    auto sh = shifts.mutable_unchecked<2>();
    auto sv = side_vertices.mutable_unchecked<2>();
    py::list rings;
    py::ssize_t s = 0;
    for (py::ssize_t k = 0; k < n; ++k) {
        const Cell& x = t.cells[static_cast<std::size_t>(k)];
        site_area.mutable_at(k) = x.site_area.mid_double();
        visible.mutable_at(k) = x.visible;
        bounded.mutable_at(k) = x.bounded;
        precision.mutable_at(k) = x.precision;
        reach.mutable_at(k) = x.reach;
        indptr.mutable_at(k) = s;
        for (const CellSide& side : x.sides) {
            // A wall as minus its number: -1 left, -2 bottom, -3 right, -4 top.
            ind(s) = side.neighbor >= 0 ? side.neighbor : -static_cast<std::int64_t>(side.wall);
            sh(s, 0) = side.shift[0], sh(s, 1) = side.shift[1];
            sv(s, 0) = side.from, sv(s, 1) = side.to;
            ++s;
        }
        auto ring = new_array<double>({static_cast<py::ssize_t>(x.ring.size()), 2});
        auto r = ring.mutable_unchecked<2>();
        for (std::size_t p = 0; p < x.ring.size(); ++p)
            r(static_cast<py::ssize_t>(p), 0) = x.ring[p][0], r(static_cast<py::ssize_t>(p), 1) = x.ring[p][1];
        rings.append(ring);
    }
    indptr.mutable_at(n) = s;
    const auto nv = static_cast<py::ssize_t>(t.vertices.size());
    auto vlo = new_array<double>({nv, 2}), vhi = new_array<double>({nv, 2});
    auto vsites = new_array<std::int64_t>({nv, 3}), vwalls = new_array<std::int64_t>({nv, 3});
    auto vshifts = new_array<std::int64_t>({nv, 3, 2});
    for (py::ssize_t v = 0; v < nv; ++v) {
        const CellVertex& p = t.vertices[static_cast<std::size_t>(v)];
        std::tie(vlo.mutable_at(v, 0), vhi.mutable_at(v, 0)) = double_bounds(p.x);
        std::tie(vlo.mutable_at(v, 1), vhi.mutable_at(v, 1)) = double_bounds(p.y);
        for (py::ssize_t i = 0; i < 3; ++i) {
            const CellSiteImage& f = p.face[static_cast<std::size_t>(i)];
            vsites.mutable_at(v, i) = f.site;
            vwalls.mutable_at(v, i) = static_cast<std::int64_t>(f.wall);
            vshifts.mutable_at(v, i, 0) = f.shift[0], vshifts.mutable_at(v, i, 1) = f.shift[1];
        }
    }
    out["site_area"] = site_area;
    out["visible"] = visible;
    out["bounded"] = bounded;
    out["precision"] = precision;
    out["reach"] = reach;
    out["vertex_sites"] = vsites;
    out["vertex_walls"] = vwalls;
    out["vertex_shifts"] = vshifts;
    out["indptr"] = indptr;
    out["indices"] = indices;
    out["shifts"] = shifts;
    out["side_vertices"] = side_vertices;
    out["vertices_lo"] = vlo;
    out["vertices_hi"] = vhi;
    out["rings"] = rings;
    out["boundary_tolerance"] = t.boundary_tolerance;
    const char* kinds[] = {"plane", "box", "periodic"};
    out["domain"] = kinds[static_cast<int>(t.domain.kind)];
    if (t.domain.kind != CellDomain::Kind::plane)
        out["box"] = py::make_tuple(to_fraction(t.domain.x0), to_fraction(t.domain.y0), to_fraction(t.domain.x1),
                                    to_fraction(t.domain.y1));
    return out;
}

// The JSON or GeoJSON document of the cells, with its newline.
void write_document(std::ostream& out, const Cells& c, const std::string& format) {
    if (format == "geojson")
        write_cells_geojson(out, c.t);
    else
        write_cells_json(out, c.t);
    out << "\n";
}

std::string document(const Cells& c, const std::string& format) {
    std::ostringstream out;
    write_document(out, c, format);
    return out.str();
}

}  // namespace

void bind_cells(py::module_& m) {
    py::class_<Cells, std::unique_ptr<Cells>>(m, "_Cells")
        .def("arrays", &arrays)
        .def("json", [](const Cells& c) { return document(c, "json"); })
        .def("geojson", [](const Cells& c) { return document(c, "geojson"); })
        .def("write", [](const Cells& c, const std::string& path, const std::string& format) {
            py::gil_scoped_release release;
            write_file_atomically(path, [&](std::ostream& o) { write_document(o, c, format); });
        });
    m.def("_cells", &cells, py::arg("sites"), py::arg("box"), py::arg("periodic"), py::arg("tolerance"),
          py::arg("boundary_tolerance"), py::arg("rings"), py::arg("only") = std::vector<SiteId>{},
          py::arg("threads") = 1U);
    m.def("_check_cells", &check_cells, py::arg("sites"), py::arg("box"), py::arg("periodic"), py::arg("tolerance"),
          py::arg("boundary_tolerance"));
}

}  // namespace ellvor::python
