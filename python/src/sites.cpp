// ellvor.Ellipse, ellvor.Sites, read_sites and generate.
#include "python/src/bindings.hpp"

#include "sites/packing_generator.hpp"
#include "sites/site_generators.hpp"
#include "util/error.hpp"

#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace ellvor::python {
namespace {

SiteFormat site_format(const std::string& format) {
    if (format == "ell") return SiteFormat::ell;
    if (format == "cin") return SiteFormat::cin;
    throw py::value_error("fmt: expected 'ell' or 'cin', got '" + format + "'");
}

// The reader's per-site checks (sites/site_io.cpp), for an ellipse made from values.
Ellipse checked_ellipse(Rational a, Rational b, Rational w, Rational xc, Rational yc) {
    if (a.sign() <= 0) throw InputError("semi-axis a must be positive, found " + a.str());
    if (b.sign() <= 0) throw InputError("semi-axis b must be positive, found " + b.str());
    Rational smaller = a < b ? a : b;
    fmpq_mul_2exp(smaller.get(), smaller.get(), kMaxAspectBits);
    if ((a < b ? b : a) > smaller)
        throw InputError("semi-axes " + a.str() + " and " + b.str() + " differ by more than a factor 2^" +
                         std::to_string(kMaxAspectBits) + ", the largest ratio ellvor supports");
    return Ellipse(std::move(a), std::move(b), std::move(w), std::move(xc), std::move(yc));
}

Ellipse make_ellipse(py::handle a, py::handle b, py::handle w, py::handle xc, py::handle yc) {
    return checked_ellipse(to_rational(a, "a"), to_rational(b, "b"), to_rational(w, "w"), to_rational(xc, "xc"),
                           to_rational(yc, "yc"));
}

std::string repr(const Ellipse& e) {
    std::string s = "Ellipse(";
    const Rational* values[] = {&e.a(), &e.b(), &e.w(), &e.xc(), &e.yc()};
    for (int k = 0; k < 5; ++k) s += (k ? ", '" : "'") + values[k]->str() + "'";
    return s + ")";
}

std::string path_string(py::handle path) {
    return py::cast<std::string>(py::module_::import("os").attr("fsdecode")(path));
}

bool is_path(py::handle value) {
    return PyUnicode_Check(value.ptr()) || PyBytes_Check(value.ptr()) || py::hasattr(value, "__fspath__");
}

Sites read_site_path(py::handle path, const std::string& format) {
    const SiteFormat f = site_format(format);
    const std::string p = path_string(path);
    Sites s;
    {
        py::gil_scoped_release release;
        s.file = read_site_file(p, f);
    }
    s.from_file = true;
    return s;
}

// Sites from text held in memory: the lines a tiled build ships to a worker,
// or a whole file's text (python/ellvor/distributed.py), parsed as a file's
// are, without one Python object per site. With a `name`, they count as read
// from that file, so that errors found in the build point at its lines, as
// the CLI's do; without, errors name sites by id, which the caller maps back.
Sites sites_from_text(const std::string& text, const std::string& format, py::object name) {
    const SiteFormat f = site_format(format);
    Sites s;
    s.from_file = !name.is_none();
    const std::string display = s.from_file ? py::str(name).cast<std::string>() : "<sites>";
    py::gil_scoped_release release;
    std::istringstream in(text);
    SiteFile file = read_site_file(in, display, f);
    if (!s.from_file) file.lines.clear();
    s.file = std::move(file);
    return s;
}

// One site's row of each of tiling_arrays' arrays: its fractions (false when
// one needs more than 64 bits), nearest doubles and box. A box is the rotated
// ellipse's extent about the rounded center, widened by 2^-40 of
// |center| + a + b: the rounding of the parameters (half an ulp each) and of
// the dozen operations below are far below that.
bool tiling_values(const Ellipse& e, std::int64_t* f, double* p, double* b) {
    constexpr std::int64_t kExactInteger = std::int64_t{1} << 53;
    constexpr double kMargin = 0x1p-40;
    const Rational* values[] = {&e.a(), &e.b(), &e.w(), &e.xc(), &e.yc()};
    bool fits = true;
    for (int j = 0; j < 5; ++j) {
        const fmpz *num = fmpq_numref(values[j]->get()), *den = fmpq_denref(values[j]->get());
        const bool small = fmpz_fits_si(num) && fmpz_fits_si(den);
        const std::int64_t nv = small ? fmpz_get_si(num) : 0, dv = small ? fmpz_get_si(den) : 1;
        fits = fits && small;
        f[2 * j] = nv;
        f[2 * j + 1] = dv;
        // Integers below 2^53 are exact doubles: one correctly rounded
        // division is then the nearest double (to_double costs ~1 µs).
        const bool exact = small && nv > -kExactInteger && nv < kExactInteger && dv < kExactInteger;
        p[j] = exact ? static_cast<double>(nv) / static_cast<double>(dv) : values[j]->to_double();
    }
    const double a = p[0], bb = p[1], w = p[2], xc = p[3], yc = p[4];
    const double c = (1 - w * w) / (1 + w * w), sn = 2 * w / (1 + w * w);  // w = tan(angle / 2)
    const double hx = std::sqrt((a * c) * (a * c) + (bb * sn) * (bb * sn));
    const double hy = std::sqrt((a * sn) * (a * sn) + (bb * c) * (bb * c));
    const double mx = kMargin * (std::fabs(xc) + a + bb) + 5e-324, my = kMargin * (std::fabs(yc) + a + bb) + 5e-324;
    b[0] = std::nextafter(xc - hx - mx, -HUGE_VAL);
    b[1] = std::nextafter(xc + hx + mx, HUGE_VAL);
    b[2] = std::nextafter(yc - hy - my, -HUGE_VAL);
    b[3] = std::nextafter(yc + hy + my, HUGE_VAL);
    return fits;
}

// The fractions narrowed to T (every value fits).
template <class T>
py::array_t<T> narrowed(const py::array_t<std::int64_t>& wide) {
    auto out = new_array<T>({wide.shape(0), wide.shape(1)});
    std::copy(wide.data(), wide.data() + wide.size(), out.mutable_data());
    return out;
}

// What a tiled build (python/ellvor/distributed.py) needs of every site, in
// one pass over the sites (a pass costs their cache misses): a tuple
//   params (n, 5): the nearest doubles of a b w xc yc (as Sites.to_array);
//   fractions (n, 10): a_num a_den b_num ... yc_den, what the tiles are sent
//       (no text to format or parse), in the narrowest of int16, int32 and
//       int64 that holds them all, or None when one needs more than 64 bits;
//   boxes (n, 4): xlo xhi ylo yhi, a box that contains the exact ellipse.
py::tuple tiling_arrays(const Sites& s) {
    const auto n = static_cast<py::ssize_t>(s.file.sites.size());
    auto params = new_array<double>({n, static_cast<py::ssize_t>(5)});
    auto fractions = new_array<std::int64_t>({n, static_cast<py::ssize_t>(10)});
    auto boxes = new_array<double>({n, static_cast<py::ssize_t>(4)});
    double* p = params.mutable_data();
    std::int64_t* f = fractions.mutable_data();
    double* b = boxes.mutable_data();
    bool fits = true;
    std::int64_t lo = 0, hi = 0;
    {
        py::gil_scoped_release release;
        // Each site's parameters sit in a block of their own: fetching those a
        // few sites ahead overlaps the cache misses that dominate this loop.
        constexpr py::ssize_t kAhead = 8;
        for (py::ssize_t k = 0; k < n; ++k) {
            if (k + kAhead < n) s.file.sites[static_cast<std::size_t>(k + kAhead)].prefetch();
            fits = tiling_values(s.file.sites[static_cast<std::size_t>(k)], f + 10 * k, p + 5 * k, b + 4 * k) && fits;
            const auto [row_lo, row_hi] = std::minmax_element(f + 10 * k, f + 10 * k + 10);
            lo = std::min(lo, *row_lo), hi = std::max(hi, *row_hi);
        }
    }
    using Short = std::numeric_limits<std::int16_t>;
    using Int = std::numeric_limits<std::int32_t>;
    py::object sent = py::none();
    if (fits && lo >= Short::min() && hi <= Short::max())
        sent = narrowed<std::int16_t>(fractions);
    else if (fits && lo >= Int::min() && hi <= Int::max())
        sent = narrowed<std::int32_t>(fractions);
    else if (fits)
        sent = std::move(fractions);
    return py::make_tuple(params, sent, boxes);
}

}  // namespace

py::array_t<double> site_boxes(const std::vector<Ellipse>& sites) {
    const auto n = static_cast<py::ssize_t>(sites.size());
    auto boxes = new_array<double>({n, static_cast<py::ssize_t>(4)});
    double* b = boxes.mutable_data();
    py::gil_scoped_release release;
    std::int64_t f[10];
    double p[5];
    for (py::ssize_t k = 0; k < n; ++k) tiling_values(sites[static_cast<std::size_t>(k)], f, p, b + 4 * k);
    return boxes;
}

// Sites from tiling_arrays' fractions, checked as a list of Ellipses is.
Sites sites_from_fractions(py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> fractions) {
    if (fractions.ndim() != 2 || fractions.shape(1) != 10)
        throw py::value_error("_sites_from_fractions: expected a (k, 10) array");
    const auto f = fractions.unchecked<2>();
    Sites s;
    py::gil_scoped_release release;
    s.file.sites.reserve(static_cast<std::size_t>(f.shape(0)));
    for (py::ssize_t k = 0; k < f.shape(0); ++k) {
        std::array<Rational, 5> r;
        for (int j = 0; j < 5; ++j) {
            const std::int64_t num = f(k, 2 * j), den = f(k, 2 * j + 1);
            if (den <= 0) throw InputError("_sites_from_fractions: a denominator is not positive");
            fmpz_set_si(fmpq_numref(r[j].get()), num);
            fmpz_set_si(fmpq_denref(r[j].get()), den);
            fmpq_canonicalise(r[j].get());
        }
        s.file.sites.push_back(checked_ellipse(std::move(r[0]), std::move(r[1]), std::move(r[2]), std::move(r[3]),
                                               std::move(r[4])));
    }
    check_site_set(s.file);
    return s;
}

namespace {

Sites list_of_sites(py::iterable sites) {
    Sites s;
    for (py::handle item : sites) {
        if (!py::isinstance<Ellipse>(item))
            throw py::type_error("sites: expected Ellipse objects, got " +
                                 py::cast<std::string>(py::type::handle_of(item).attr("__name__")));
        s.file.sites.push_back(py::cast<const Ellipse&>(item));
    }
    check_site_set(s.file);
    return s;
}

// The nearest doubles, (n, 5): a b w xc yc.
py::array_t<double> sites_array(const Sites& s) {
    auto out = new_array<double>({static_cast<py::ssize_t>(s.file.sites.size()), 5});
    auto w = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < s.file.sites.size(); ++i) {
        const Ellipse& e = s.file.sites[i];
        const Rational* values[] = {&e.a(), &e.b(), &e.w(), &e.xc(), &e.yc()};
        for (int k = 0; k < 5; ++k) w(static_cast<py::ssize_t>(i), k) = values[k]->to_double();
    }
    return out;
}

// `ellvor generate packing` (sites/packing_generator.hpp), with its checks as ValueErrors.
Sites generate_packing_sites(long count, std::uint64_t seed, py::handle packing_fraction, py::handle gap,
                             py::handle aspect) {
    if (count < kMinPackingCount || count > 1'000'000)
        throw py::value_error("count: expected an integer in [" + std::to_string(kMinPackingCount) +
                              ", 1000000] for 'packing'");
    if (packing_fraction.is_none()) throw py::value_error("packing_fraction: required for 'packing'");
    PackingOptions o;
    o.count = count;
    o.seed = seed;
    o.fraction = to_rational(packing_fraction, "packing_fraction");
    if (o.fraction.sign() <= 0 || o.fraction > max_packing_fraction())
        throw py::value_error("packing_fraction: expected a rational in (0, " + max_packing_fraction().str() +
                              "], got " + o.fraction.str());
    if (!gap.is_none()) o.gap = to_rational(gap, "gap");
    if (o.gap.sign() < 0 || o.gap > Rational(1, 10))
        throw py::value_error("gap: expected a rational in [0, 1/10], got " + o.gap.str());
    if (!aspect.is_none()) {
        const auto range = aspect.cast<py::tuple>();
        if (range.size() != 2) throw py::value_error("aspect: expected a pair (lo, hi)");
        o.aspect_lo = to_rational(range[0], "aspect");
        o.aspect_hi = to_rational(range[1], "aspect");
    }
    if (o.aspect_lo < Rational(1) || o.aspect_hi < o.aspect_lo || o.aspect_hi > Rational(16))
        throw py::value_error("aspect: expected 1 <= lo <= hi <= 16, got (" + o.aspect_lo.str() + ", " +
                              o.aspect_hi.str() + ")");
    Sites s;
    {
        py::gil_scoped_release release;
        try {
            s.file.sites = generate_packing(o).sites;
        } catch (const Error& e) {
            throw py::value_error(e.what());  // a fraction the sites jam below, as for the CLI
        }
    }
    return s;
}

Sites generate(const std::string& kind, long count, std::uint64_t seed, long bits, py::handle box,
               py::handle nested_fraction, py::handle crossing, py::handle packing_fraction, py::handle gap,
               py::handle aspect) {
    if (kind == "packing") return generate_packing_sites(count, seed, packing_fraction, gap, aspect);
    if (!packing_fraction.is_none() || !gap.is_none() || !aspect.is_none())
        throw py::value_error("packing_fraction, gap and aspect apply to kind 'packing' only");
    // The checks of `ellvor generate` (cli/command_generate.cpp), as ValueErrors.
    if (kind != "ellipses" && kind != "circles" && kind != "nested")
        throw py::value_error("kind: expected 'ellipses', 'circles', 'nested' or 'packing', got '" + kind + "'");
    if (count < 0 || count > 1'000'000) throw py::value_error("count: expected an integer in [0, 1000000]");
    if (bits < 1 || bits > kMaxGeneratorBits)
        throw py::value_error("bits: expected an integer in [1, " + std::to_string(kMaxGeneratorBits) + "]");
    GeneratorOptions o;
    o.kind = kind == "circles" ? SiteKind::circles : SiteKind::ellipses;
    o.count = count;
    o.seed = seed;
    o.bits = bits;
    o.box = to_rational(box, "box");
    if (o.box.sign() <= 0 || o.box.bits() > 64)
        throw py::value_error("box: expected a positive rational with at most 64-bit numerator and denominator");
    o.nested_fraction = nested_fraction.is_none() ? (kind == "nested" ? Rational(1, 4) : Rational(0))
                                                  : to_rational(nested_fraction, "nested_fraction");
    if (o.nested_fraction.sign() < 0 || o.nested_fraction >= Rational(1))
        throw py::value_error("nested_fraction: expected a rational in [0, 1), got " + o.nested_fraction.str());
    o.crossing_fraction = to_rational(crossing, "crossing");
    if (o.crossing_fraction.sign() < 0 || o.crossing_fraction > Rational(1))
        throw py::value_error("crossing: expected a rational in [0, 1], got " + o.crossing_fraction.str());
    Sites s;
    {
        py::gil_scoped_release release;
        try {
            s.file.sites = generate_sites(o);
        } catch (const Error& e) {
            throw py::value_error(e.what());  // too many sites for the box: bad arguments, as for the CLI
        }
    }
    return s;
}

void write_sites(const Sites& s, py::handle path, const std::string& format) {
    const SiteFormat f = site_format(format);
    const std::string p = path_string(path);
    py::gil_scoped_release release;
    write_file_atomically(p, [&](std::ostream& out) {
        if (f == SiteFormat::cin) write_cin(out, s.file.sites);
        else write_ell(out, s.file.sites);
    });
}

}  // namespace

Sites sites_argument(py::handle value, const std::string& format) {
    if (py::isinstance<Sites>(value)) return py::cast<const Sites&>(value);
    if (is_path(value)) return read_site_path(value, format);
    if (!py::isinstance<py::iterable>(value))
        throw py::type_error("expected a path, a Sites object or an iterable of Ellipse");
    return list_of_sites(py::reinterpret_borrow<py::iterable>(value));
}

void bind_sites(py::module_& m) {
    py::class_<Ellipse>(m, "Ellipse")
        .def(py::init(&make_ellipse), py::arg("a"), py::arg("b"), py::arg("w") = 0, py::arg("xc") = 0,
             py::arg("yc") = 0)
        .def_static(
            "circle",
            [](py::handle x, py::handle y, py::handle r) {
                const Rational radius = to_rational(r, "r");
                return checked_ellipse(radius, radius, Rational(0), to_rational(x, "x"), to_rational(y, "y"));
            },
            py::arg("x"), py::arg("y"), py::arg("r"))
        .def_property_readonly("a", [](const Ellipse& e) { return to_fraction(e.a()); })
        .def_property_readonly("b", [](const Ellipse& e) { return to_fraction(e.b()); })
        .def_property_readonly("w", [](const Ellipse& e) { return to_fraction(e.w()); })
        .def_property_readonly("xc", [](const Ellipse& e) { return to_fraction(e.xc()); })
        .def_property_readonly("yc", [](const Ellipse& e) { return to_fraction(e.yc()); })
        .def_property_readonly("is_circle", &Ellipse::is_circle)
        .def("same_point_set", [](const Ellipse& e, const Ellipse& o) { return e.point_set_key() == o.point_set_key(); })
        .def("__str__", &Ellipse::str)
        .def("__repr__", &repr)
        .def("__eq__", [](const Ellipse& e, const Ellipse& o) { return e == o; })
        .def("__hash__", [](const Ellipse& e) { return py::hash(py::str(e.str())); })
        .def(py::pickle([](const Ellipse& e) { return py::make_tuple(e.str()); },
                        [](py::tuple t) {
                            const std::string text = py::cast<std::string>(t[0]);
                            std::istringstream in(text);
                            return read_sites(in, "<pickle>").at(0);
                        }));

    py::class_<Sites>(m, "Sites")
        .def(py::init([](py::iterable sites) { return list_of_sites(sites); }), py::arg("sites"))
        .def("__len__", [](const Sites& s) { return s.file.sites.size(); })
        .def("__getitem__",
             [](const Sites& s, long i) {
                 const long n = static_cast<long>(s.file.sites.size());
                 if (i < 0) i += n;
                 if (i < 0 || i >= n) throw py::index_error("site index out of range");
                 return s.file.sites[static_cast<std::size_t>(i)];
             })
        .def_property_readonly("filename",
                               [](const Sites& s) -> py::object {
                                   if (!s.from_file) return py::none();
                                   return py::str(s.file.name);
                               })
        .def_property_readonly("lines",
                               [](const Sites& s) -> py::object {
                                   if (!s.from_file) return py::none();
                                   auto out = new_array<std::int64_t>({static_cast<py::ssize_t>(s.file.lines.size())});
                                   std::copy(s.file.lines.begin(), s.file.lines.end(), out.mutable_data());
                                   return std::move(out);
                               })
        .def("to_array", &sites_array)
        // The .ell lines (str(e)) of the sites `ids`, joined by newlines: the text a tiled build
        // sends a tile (python/ellvor/distributed.py), made without a Python string a site.
        .def("_lines",
             [](const Sites& s, py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> ids) {
                 const auto v = ids.unchecked<1>();
                 const auto n = static_cast<std::int64_t>(s.file.sites.size());
                 for (py::ssize_t k = 0; k < v.shape(0); ++k)
                     if (v(k) < 0 || v(k) >= n) throw py::index_error("_lines: site id out of range");
                 std::string out;
                 {
                     py::gil_scoped_release release;
                     for (py::ssize_t k = 0; k < v.shape(0); ++k) {
                         if (k) out += '\n';
                         out += s.file.sites[static_cast<std::size_t>(v(k))].str();
                     }
                 }
                 return out;
             },
             py::arg("ids"))
        .def("_tiling_arrays", &tiling_arrays)
        .def("write", &write_sites, py::arg("path"), py::arg("fmt") = "ell")
        .def("__repr__", [](const Sites& s) {
            return "<ellvor.Sites: " + std::to_string(s.file.sites.size()) + " sites" +
                   (s.from_file ? " from " + s.file.name : std::string()) + ">";
        });

    // The error `ellvor.build(sites)` raises for sites `first` and `second` that
    // cross as `why` says: at the later site's line when the sites are a file's.
    m.def(
        "_raise_crossing_sites",
        [](const Sites& s, std::size_t first, std::size_t second, const std::string& why) {
            const std::size_t n = s.file.sites.size();
            if (first >= n || second >= n) throw py::index_error("_raise_crossing_sites: site id out of range");
            if (s.from_file) throw crossing_sites_error(s.file, first, second, why);
            throw IntersectingSites(std::min(first, second), std::max(first, second), why);
        },
        py::arg("sites"), py::arg("first"), py::arg("second"), py::arg("why"));
    m.def("_sites_from_fractions", &sites_from_fractions, py::arg("fractions"));
    m.def("_sites_from_text", &sites_from_text, py::arg("text"), py::arg("fmt") = "ell", py::arg("name") = py::none());
    m.def("read_sites", &read_site_path, py::arg("path"), py::arg("fmt") = "ell");
    m.def("generate", &generate, py::arg("kind") = "ellipses", py::arg("count") = 10, py::arg("seed") = 1,
          py::arg("bits") = 8, py::arg("box") = 100, py::arg("nested_fraction") = py::none(), py::arg("crossing") = 0,
          py::arg("packing_fraction") = py::none(), py::arg("gap") = py::none(), py::arg("aspect") = py::none(),
          "Random sites as `ellvor generate KIND --count COUNT ...` writes them: the same\n"
          "arguments give the same Sites on every machine. kind is 'ellipses', 'circles'\n"
          "or 'nested' (ellipses, nested_fraction 1/4 by default); numbers are exact (an\n"
          "int, a Fraction, a str such as '0.3'). Exactly round(nested_fraction * count)\n"
          "sites lie inside another; exactly round(crossing * count) cross at least one\n"
          "other site, their boundaries meeting in exactly two points, and the others\n"
          "cross none (nested sites never cross; a count of 1 is a ValueError). Raises\n"
          "ValueError for bad arguments or too many sites for the box.\n"
          "kind 'packing' (`ellvor generate packing`): count (>= 30) random ellipses in the\n"
          "box [0, L]^2, L = ceil(sqrt(count)), at packing fraction pi sum(a b) / L^2 >=\n"
          "packing_fraction (required), every two at distance >= gap (default 1/1000,\n"
          "certified), aspect ratios in aspect = (lo, hi) (default (1, 4)); a fraction the\n"
          "sites jam below is a ValueError saying the fraction reached. bits, box,\n"
          "nested_fraction and crossing do not apply.");
}

}  // namespace ellvor::python
