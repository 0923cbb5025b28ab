// The C++ half of the Python module ellvor (python/ellvor/ is the Python
// half): pybind11 bindings over the library, as the CLI is a program over it
// (docs/DESIGN.md §8). Exact values cross the boundary exactly (Python ints,
// Fractions), arrays as NumPy arrays filled here, errors as ellvor.Error and
// ellvor.InputError (python/ellvor/_errors.py).
#pragma once

#include "sites/site_io.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "util/flint_types.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ellvor::python {

namespace py = pybind11;

// ---- numbers (conversions.cpp) ----------------------------------------------------------------------------

// A Python number as an exact Rational: an int; a float, exactly (as
// Fraction(float) does: 0.1 is 3602879701896397/2^55); a str in the .ell
// grammar (sites/rational_parse.hpp: "0.1" is 1/10); anything else with
// integer `numerator` and `denominator` (Fraction, gmpy2.mpq). NaN, infinities,
// zero denominators and numbers beyond kMaxRationalBits are refused with an
// InputError naming `what` before FLINT sees them (FLINT aborts on a zero
// denominator). bool is refused (a TypeError): True is no coordinate.
Rational to_rational(py::handle value, const std::string& what);
py::int_ to_python_int(const Integer& z);
py::object to_fraction(const Rational& q);

// ---- sites (sites.cpp) --------------------------------------------------------------------------------------

// A site list as Python sees it: the sites and, when they were read from a
// file, its name and lines (so that errors found later point at lines, as the
// CLI's do). Immutable once made.
struct Sites {
    SiteFile file;
    bool from_file = false;
};

// Sites from a Sites object, or a str / os.PathLike path read as `format`
// ("ell" or "cin"), or any iterable of Ellipse (checked as a set:
// duplicates, dynamic range).
Sites sites_argument(py::handle value, const std::string& format);
// Sites from (k, 10) int64 numerator/denominator pairs (Sites._tiling_arrays),
// checked as a list of Ellipses is.
Sites sites_from_fractions(py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> fractions);
// Per site (xlo, xhi, ylo, yhi): the boxes Sites._tiling_arrays gives, each containing its exact ellipse.
py::array_t<double> site_boxes(const std::vector<Ellipse>& sites);

// ---- NumPy arrays (filled from C++, no Python loop) ---------------------------------------------------------

template <class T>
py::array_t<T> new_array(std::vector<py::ssize_t> shape) {
    return py::array_t<T>(shape);
}

// Pairs as an (n, 2) int64 array.
template <class Pairs>
py::array_t<std::int64_t> pairs_array(const Pairs& pairs) {
    auto out = new_array<std::int64_t>({static_cast<py::ssize_t>(pairs.size()), 2});
    auto w = out.template mutable_unchecked<2>();
    py::ssize_t k = 0;
    for (const auto& [a, b] : pairs) {
        w(k, 0) = static_cast<std::int64_t>(a);
        w(k, 1) = static_cast<std::int64_t>(b);
        ++k;
    }
    return out;
}

// ---- the parts of the module ---------------------------------------------------------------------------------

void register_errors(py::module_& m);
void bind_sites(py::module_& m);
void bind_diagram(py::module_& m);
void bind_cells(py::module_& m);
void bind_predicates(py::module_& m);

// An arb ball for Python: (lo, hi, text) with exact dyadic Fraction bounds
// and Arb's "[mid +/- rad]" text at the digits the CLI prints for `bits`.
py::tuple ball_tuple(const Ball& b, long bits);

// A certified Voronoi circle for Python (predicates.cpp): center, radius and
// tangency parameters as ball tuples, with the certificate's figures.
py::dict enclosure_dict(const VoronoiCircleEnclosure& c, long bits);

}  // namespace ellvor::python
