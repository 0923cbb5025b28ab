// ellvor.incircle, ellvor.voronoi_circle and ellvor.side_of_bisector: the
// predicates of `ellvor incircle`, `voronoi-circle` and `side-of-bisector`,
// with the same answers, stages and checks of their sites.
#include "python/src/bindings.hpp"

#include "predicates/incircle.hpp"
#include "predicates/relative_position.hpp"
#include "predicates/side_of_bisector.hpp"
#include "predicates/voronoi_circle_count.hpp"
#include "util/error.hpp"
#include "util/precision.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <chrono>

namespace ellvor::python {
namespace {

using Clock = std::chrono::steady_clock;

// The checks the CLI makes of a predicate's site file (the reader's set
// checks, then no pair meeting in 3 or 4 points); errors name the sites by position.
void require_valid_sites(const std::vector<const Ellipse*>& sites) {
    SiteFile file;
    for (const Ellipse* e : sites) file.sites.push_back(*e);
    check_site_set(file);
    require_acceptable_crossings(file.sites);
}

double microseconds_since(Clock::time_point start) {
    return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
}

py::dict incircle_answer(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, const Ellipse& q,
                         long max_precision) {
    if (max_precision < precision::kStart || max_precision > precision::kMaxCap)
        throw py::value_error("max_precision: expected an integer in [" + std::to_string(precision::kStart) + ", " +
                              std::to_string(precision::kMaxCap) + "]");
    InCircleOptions options;
    options.refinement.cap = max_precision;
    Decision<InCircle> d;
    long newton_steps = 0;
    double us = 0;
    {
        py::gil_scoped_release release;
        require_valid_sites({&e1, &e2, &e3, &q});
        const Clock::time_point start = Clock::now();
        VoronoiCircle circle(e1, e2, e3, common_medial_axis_tangency);
        d = incircle(e1, e2, e3, q, options, &circle);
        newton_steps = circle.has_solver() ? circle.solver().enclosure().newton_steps : 0;
        us = microseconds_since(start);
    }
    py::dict out;
    out["result"] = incircle_name(*d);
    out["sign"] = to_int(incircle_sign(*d));
    out["stage"] = stage_name(d.stage);
    out["precision"] = d.precision;
    out["newton_steps"] = newton_steps;
    out["time_us"] = us;
    return out;
}

py::dict side_of_bisector_answer(const Ellipse& e1, const Ellipse& e2, py::handle point) {
    const py::sequence xy = py::reinterpret_borrow<py::sequence>(point);
    if (!py::isinstance<py::sequence>(point) || py::len(xy) != 2)
        throw py::type_error("point: expected a pair (x, y)");
    const Point p{to_rational(xy[0], "x"), to_rational(xy[1], "y")};
    Decision<Sign> d;
    double us = 0;
    {
        py::gil_scoped_release release;
        require_valid_sites({&e1, &e2});
        const Clock::time_point start = Clock::now();
        d = side_of_bisector(e1, e2, p);
        us = microseconds_since(start);
    }
    py::dict out;
    out["result"] = *d == Sign::positive ? "first" : *d == Sign::negative ? "second" : "equidistant";
    out["sign"] = to_int(*d);
    out["stage"] = stage_name(d.stage);
    out["precision"] = d.precision;
    out["time_us"] = us;
    return out;
}

py::dict voronoi_circle_answer(const Ellipse& e1, const Ellipse& e2, const Ellipse& e3, long bits) {
    if (bits < 1 || bits > 10'000'000) throw py::value_error("bits: expected an integer in [1, 10^7]");
    Decision<VoronoiCircles> count;
    std::unique_ptr<VoronoiCircleSolver> solver;
    double ms = 0;
    {
        py::gil_scoped_release release;
        require_valid_sites({&e1, &e2, &e3});
        count = voronoi_circle_count(e1, e2, e3);
        if (*count == VoronoiCircles::ccw_only || *count == VoronoiCircles::both) {
            const Clock::time_point start = Clock::now();
            solver = std::make_unique<VoronoiCircleSolver>(e1, e2, e3, common_medial_axis_tangency);
            solver->refine_existing(bits);  // the count proved it exists
            ms = microseconds_since(start) / 1000;
        }
    }
    py::dict out = solver ? enclosure_dict(solver->enclosure(), bits) : py::dict();
    out["exists"] = solver != nullptr;
    out["circles"] = voronoi_circles_name(*count);
    out["stage"] = stage_name(count.stage);  // the stage that decided the count
    out["bits"] = bits;
    if (solver) out["time_ms"] = ms;
    return out;
}

}  // namespace

py::dict enclosure_dict(const VoronoiCircleEnclosure& c, long bits) {
    py::dict out;
    out["center"] = py::make_tuple(ball_tuple(c.center_x, bits), ball_tuple(c.center_y, bits));
    out["radius"] = ball_tuple(c.radius, bits);
    py::list tangency;
    for (int i = 0; i < 3; ++i) {
        py::dict t;
        t["chart"] = c.flipped[i] ? "-1/t" : "t";
        t["chart_parameter"] = ball_tuple(c.parameter[i], bits);
        // As the CLI: t is infinite (None here, "inf" there) when the box holds the i-point.
        t["t"] = c.flipped[i] && arb_contains_zero(c.parameter[i].get())
                     ? py::object(py::none())
                     : py::object(ball_tuple(c.tangency_parameter(i, c.precision), bits));
        tangency.append(t);
    }
    out["tangency"] = tangency;
    out["correct_bits"] = c.correct_bits();
    out["precision"] = c.precision;
    out["newton_steps"] = c.newton_steps;
    out["found_by"] = circle_start_name(c.found_by);
    out["search_boxes"] = c.search_boxes;
    return out;
}

void bind_predicates(py::module_& m) {
    m.def("_incircle", &incircle_answer, py::arg("e1"), py::arg("e2"), py::arg("e3"), py::arg("q"),
          py::arg("max_precision"));
    m.def("_side_of_bisector", &side_of_bisector_answer, py::arg("e1"), py::arg("e2"), py::arg("point"));
    m.def("_voronoi_circle", &voronoi_circle_answer, py::arg("e1"), py::arg("e2"), py::arg("e3"), py::arg("bits"));
}

}  // namespace ellvor::python
