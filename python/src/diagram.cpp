// ellvor.build and the diagram it returns (python/ellvor/_diagram.py wraps it).
#include "python/src/bindings.hpp"

#include "cells/voronoi_cells.hpp"
#include "graph/delaunay_graph.hpp"
#include "output/bisector_trace.hpp"
#include "output/graph_json.hpp"
#include "output/voronoi_circle_box.hpp"
#include "output/voronoi_ridges.hpp"
#include "traits/ellipse_delaunay_traits.hpp"
#include "subdivision/voronoi_circle_enclosure.hpp"
#include "util/error.hpp"
#include "exact/medial_axis_tangency.hpp"

#include <pybind11/stl.h>

#include <sstream>
#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>

namespace ellvor::python {
namespace {

using Clock = std::chrono::steady_clock;

// Thrown through DelaunayGraph::insert_all when Python asked to stop (Ctrl-C
// or an exception of the progress callback); the Python error itself waits
// in the hook until the GIL is back.
struct Interrupted {};

// Called after every insertion with the GIL released. Every 50 ms it takes
// the GIL to run Python's signal handlers (so Ctrl-C stops the build between
// two insertions), and it calls the progress callback on the first
// insertion, the last, and every `interval` seconds between. Taking the GIL
// only that often keeps its cost out of the build, and other Python threads
// run meanwhile.
class ProgressHook {
public:
    ProgressHook(py::object callback, double interval)
        : callback_(std::move(callback)),
          interval_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(interval))) {}

    void operator()(std::size_t done, std::size_t total) {
        const Clock::time_point now = Clock::now();
        const bool signals_due = now >= next_signal_check_;
        const bool callback_due = !callback_.is_none() && (done == 1 || done == total || now >= next_callback_);
        if (!signals_due && !callback_due) return;
        py::gil_scoped_acquire gil;
        try {
            if (signals_due) {
                next_signal_check_ = now + std::chrono::milliseconds(50);
                if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            }
            if (callback_due) {
                next_callback_ = now + interval_;
                callback_(done, total);
            }
        } catch (py::error_already_set& e) {
            error_ = std::move(e);
            throw Interrupted{};
        }
    }

    // Raises the stored Python error, if any (with the GIL held).
    void rethrow() {
        if (error_) {
            py::error_already_set e = std::move(*error_);
            error_.reset();
            throw e;
        }
    }

private:
    py::object callback_;
    Clock::duration interval_;
    Clock::time_point next_signal_check_ = Clock::now() + std::chrono::milliseconds(50), next_callback_{};
    std::optional<py::error_already_set> error_;
};

// graph.faces(), sorted, put in place by the numbers face_numbers gave them
// (it sorted the same triples): 2n faces not sorted twice.
std::vector<std::array<SiteId, 3>> faces_by_number(const DelaunayGraph& graph, const std::vector<long>& numbers) {
    const Triangulation& tds = graph.triangulation();
    std::vector<std::array<SiteId, 3>> out(static_cast<std::size_t>(std::count_if(
        numbers.begin(), numbers.end(), [](long k) { return k >= 0; })));
    for (FaceIndex f : tds.faces()) {
        const long k = face_number(numbers, f);
        if (k < 0) continue;
        std::array<SiteId, 3> t;
        for (int i = 0; i < 3; ++i) t[i] = tds.vertex(tds.face(f).v[i]).site();
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        out[static_cast<std::size_t>(k)] = t;
    }
    return out;
}

// A built graph and what Python reads of it. Every method that reads the
// graph releases the GIL and takes `mutex` (see locked()), so two Python
// threads may share one diagram: its predicate caches change when it is
// validated, its graph when sites are removed. Different diagrams build and
// compute in parallel.
class Diagram {
public:
    std::unique_ptr<DelaunayGraph> graph;
    const std::vector<Ellipse>* sites = nullptr;  // owned by the graph's traits; never changes
    EllipseDelaunayTraits* traits = nullptr;      // owned by the graph: its circle cache
    SiteFile names;                               // the file's name and lines (no sites)
    bool from_file = false;
    double build_seconds = 0, removal_seconds = 0;
    std::string stats;                            // as `ellvor build`'s JSON: after the build and removals
    std::vector<std::array<SiteId, 3>> faces;
    std::vector<long> numbers;                    // face_numbers(): by FaceIndex

    // After the build and after removals: what is read of the graph's state.
    void update() {
        // As `ellvor build [--remove IDS]` (cli/command_build.cpp): the counters
        // after the removals, their number and time.
        nlohmann::json s = build_stats_json(*graph, build_seconds);
        if (!graph->removed().empty()) {
            s["removed"] = graph->removed().size();
            s["removal_seconds"] = removal_seconds;
        }
        stats = s.dump();
        numbers = face_numbers(*graph);
        faces = faces_by_number(*graph, numbers);
        vertices_.reset();
    }

    // The Voronoi vertex of every face, as the JSON gives them; computed once.
    const std::vector<VoronoiVertexValue>& vertex_values() {
        if (!vertices_) {
            std::vector<VoronoiVertexValue> v;
            v.reserve(faces.size());
            for (const auto& f : faces) v.push_back(voronoi_vertex_value(*sites, f));
            vertices_ = std::move(v);
        }
        return *vertices_;
    }

    std::mutex mutex;

private:
    std::optional<std::vector<VoronoiVertexValue>> vertices_;
};

// The sites a graph's traits will own: a Sites object's copied with exact
// parameters of their own in one pass (a plain copy would share them, and
// the traits would copy each again: two passes over blocks scattered in
// memory).
Sites own_sites(py::handle sites_or_path, const std::string& format) {
    if (!py::isinstance<Sites>(sites_or_path)) return sites_argument(sites_or_path, format);
    const Sites& given = py::cast<const Sites&>(sites_or_path);
    Sites s;
    s.file.name = given.file.name;
    s.file.lines = given.file.lines;
    s.from_file = given.from_file;
    s.file.sites = Ellipse::unshared_copies(given.file.sites);
    return s;
}

// The graph of `input` (its sites moved to the graph's traits).
std::unique_ptr<Diagram> build_graph(Sites input, py::object progress, double interval) {
    auto d = std::make_unique<Diagram>();
    d->names.name = input.file.name;
    d->names.lines = input.file.lines;
    d->from_file = input.from_file;
    ProgressHook hook(std::move(progress), interval);
    bool interrupted = false;
    {
        py::gil_scoped_release release;
        // As `ellvor build` does (cli/command_build.cpp): the traits own the sites.
        auto traits = std::make_unique<EllipseDelaunayTraits>(std::move(input.file.sites));
        d->sites = &traits->sites();
        d->traits = traits.get();
        const Clock::time_point start = Clock::now();
        d->graph = std::make_unique<DelaunayGraph>(std::move(traits));
        try {
            d->graph->insert_all([&](std::size_t done, std::size_t total) { hook(done, total); });
        } catch (const Interrupted&) {
            interrupted = true;
        } catch (const IntersectingSites& e) {
            if (d->from_file) throw crossing_sites_error(d->names, e.first(), e.second(), e.why());
            throw;
        }
        if (!interrupted) {
            d->build_seconds = std::chrono::duration<double>(Clock::now() - start).count();
            d->update();
        }
    }
    hook.rethrow();
    return d;
}

std::unique_ptr<Diagram> build(py::handle sites_or_path, const std::string& format, py::object progress,
                               double interval) {
    if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
        throw py::type_error("progress: expected None or a callable(done, total)");
    if (!(interval >= 0)) throw py::value_error("progress_interval: expected a number of seconds >= 0");
    return build_graph(own_sites(sites_or_path, format), std::move(progress), interval);
}

// f(d) with the GIL released and the diagram's mutex held. Every thread
// lets the GIL go before it waits for the mutex, so a holder of the mutex
// may take the GIL (a removal checks for Ctrl-C) without a deadlock.
template <class F>
auto locked(Diagram& d, F&& f) {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(d.mutex);
    return f(d);
}

// Removes `ids` in order, as `ellvor build --remove IDS`; Ctrl-C stops
// between two removals (the sites removed until then stay removed).
void remove(Diagram& d, const std::vector<long>& ids) {
    const long n = static_cast<long>(d.sites->size());
    std::vector<SiteId> order;
    {
        std::vector<char> chosen(d.sites->size(), 0);
        for (SiteId r : locked(d, [](Diagram& g) { return g.graph->removed(); })) chosen[r] = 1;
        for (long id : ids) {
            if (id < 0 || id >= n) throw py::index_error("remove: no site " + std::to_string(id));
            if (chosen[static_cast<std::size_t>(id)])
                throw py::value_error("remove: site " + std::to_string(id) + " is removed already (or listed twice)");
            chosen[static_cast<std::size_t>(id)] = 1;
            order.push_back(static_cast<SiteId>(id));
        }
    }
    ProgressHook hook(py::none(), 0);
    const bool interrupted = locked(d, [&](Diagram& g) {
        const Clock::time_point start = Clock::now();
        bool stopped = false;
        try {
            for (std::size_t k = 0; k < order.size(); ++k) {
                g.graph->remove(order[k]);
                hook(k + 1, order.size());
            }
        } catch (const Interrupted&) {
            stopped = true;
        }
        g.removal_seconds += std::chrono::duration<double>(Clock::now() - start).count();
        g.update();
        return stopped;
    });
    if (interrupted) hook.rethrow();
}

py::array_t<std::int64_t> faces_array(const std::vector<std::array<SiteId, 3>>& faces) {
    auto out = new_array<std::int64_t>({static_cast<py::ssize_t>(faces.size()), 3});
    auto w = out.mutable_unchecked<2>();
    for (std::size_t k = 0; k < faces.size(); ++k)
        for (int i = 0; i < 3; ++i) w(static_cast<py::ssize_t>(k), i) = static_cast<std::int64_t>(faces[k][i]);
    return out;
}

py::tuple ridges(Diagram& d) {
    const std::vector<VoronoiRidge> r = locked(d, [](Diagram& g) { return voronoi_ridges(*g.graph, g.numbers); });
    std::vector<std::pair<SiteId, SiteId>> points;
    std::vector<std::pair<long, long>> ends;
    for (const VoronoiRidge& x : r) {
        points.push_back({x.p, x.q});
        ends.push_back({x.from, x.to});
    }
    return py::make_tuple(pairs_array(points), pairs_array(ends));
}

// scipy.spatial.Voronoi's regions, one per site in site order: the Voronoi
// vertices of its cell counter-clockwise (each edge's first vertex), -1 where
// the cell reaches infinity; empty for a hidden (or removed) site.
py::list regions(Diagram& d) {
    const std::vector<VoronoiCell> cells = locked(d, [](Diagram& g) { return voronoi_cells(*g.graph, g.numbers); });
    py::list out;
    for (const VoronoiCell& c : cells) {
        py::list region;
        for (const CellEdge& e : c.edges) region.append(e.from);
        out.append(region);
    }
    return out;
}

// (centers (n, 2), radii (n,), errors (n,)) as Diagram.vertices gives them.
py::tuple vertex_arrays(const std::vector<VoronoiVertexValue>& v) {
    const auto n = static_cast<py::ssize_t>(v.size());
    auto centers = new_array<double>({n, 2});
    auto radii = new_array<double>({n}), errors = new_array<double>({n});
    auto c = centers.mutable_unchecked<2>();
    auto r = radii.mutable_unchecked<1>();
    auto e = errors.mutable_unchecked<1>();
    for (py::ssize_t k = 0; k < n; ++k) {
        c(k, 0) = v[k].x, c(k, 1) = v[k].y;
        r(k) = v[k].radius;
        e(k) = v[k].error;
    }
    return py::make_tuple(centers, radii, errors);
}

py::tuple vertices(Diagram& d) {
    return vertex_arrays(locked(d, [](Diagram& g) { return g.vertex_values(); }));
}

// The Voronoi vertices of given faces (k, 3) of `sites` (counter-clockwise
// triples that have their circle, e.g. the faces a tiled build assembled),
// as Diagram.vertices gives them for its own faces.
py::tuple face_vertices(py::handle sites, py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> faces) {
    const Sites s = sites_argument(sites, "ell");
    if (faces.ndim() != 2 || faces.shape(1) != 3) throw py::value_error("faces: expected a (k, 3) array");
    const auto f = faces.unchecked<2>();
    const auto n = static_cast<std::int64_t>(s.file.sites.size());
    std::vector<std::array<SiteId, 3>> triples;
    for (py::ssize_t k = 0; k < f.shape(0); ++k) {
        std::array<SiteId, 3> t{};
        for (int i = 0; i < 3; ++i) {
            if (f(k, i) < 0 || f(k, i) >= n) throw py::index_error("faces: no site " + std::to_string(f(k, i)));
            t[i] = static_cast<SiteId>(f(k, i));
        }
        triples.push_back(t);
    }
    std::vector<VoronoiVertexValue> v;
    {
        py::gil_scoped_release release;
        for (const auto& t : triples) v.push_back(voronoi_vertex_value(s.file.sites, t));
    }
    return vertex_arrays(v);
}

std::string json(Diagram& d) {
    return locked(d, [](Diagram& g) {
        // The bytes `ellvor build --json` writes.
        std::ostringstream out;
        write_graph_json(out, *g.graph, *g.sites, nlohmann::json::parse(g.stats), g.vertex_values());
        return out.str() + "\n";
    });
}

// Per face (in `faces` order, or of the faces numbered `which`) a certified
// box of its Voronoi circle: [cx_lo, cx_hi, cy_lo, cy_hi, r_lo, r_hi],
// outward-rounded doubles, tight (output/voronoi_circle_box.hpp: the double
// certificate's box, else Arb's at 53 bits). The double certificate the build
// made is read from the traits' circle cache. The tiled build (python/ellvor/
// distributed.py) decides its seams with them.
py::array_t<double> circle_boxes(Diagram& d, std::optional<py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>> which) {
    std::vector<double> boxes;
    locked(d, [&](Diagram& g) {  // the cache is the graph's: under its lock
        const std::vector<Ellipse>& s = *g.sites;
        const std::int64_t* numbers = which ? which->data() : nullptr;
        const std::size_t count = which ? static_cast<std::size_t>(which->size()) : g.faces.size();
        boxes.reserve(6 * count);
        for (std::size_t i = 0; i < count; ++i) {
            const std::int64_t k = numbers ? numbers[i] : static_cast<std::int64_t>(i);
            if (k < 0 || static_cast<std::size_t>(k) >= g.faces.size()) throw py::index_error("which: no face " + std::to_string(k));
            const auto& f = g.faces[static_cast<std::size_t>(k)];
            VoronoiCircle* cached = g.traits->cached_circle(f[0], f[1], f[2]);
            const VoronoiCircleBox c = cached ? voronoi_circle_box(s, f, cached->in_doubles()) : voronoi_circle_box(s, f);
            boxes.insert(boxes.end(), {c.center_x.lo, c.center_x.hi, c.center_y.lo, c.center_y.hi, c.radius.lo, c.radius.hi});
        }
    });
    auto out = new_array<double>({static_cast<py::ssize_t>(boxes.size() / 6), 6});
    std::copy(boxes.begin(), boxes.end(), out.mutable_data());
    return out;
}

// The tiled build's seam certificate (python/ellvor/distributed.py, docs/
// DESIGN.md §8), per face in `faces` order: a box of its circle where
// `needed` (no other proof that its disk lies in the tile's region) or at hand
// in the circle cache, NaN elsewhere; whether a face across one of its edges
// may have the same circle (four sites on one empty circle); and whether the
// box is the double certificate's wide one (beyond 2^-40 of its circle: ~1% of
// a tile's faces, mostly huge circles along its hull; circle_boxes gives the
// tight one, ~0.3 ms a face in Arb, so only where a wide box leaves a test
// undecided). Two neighbours' circles differ when their boxes are disjoint,
// or when one box proves a site of the other off its circle: a face's circle
// is certified (~3 us) only when neither proof has the box it needs, so of
// two uncached neighbours (a late site's star) one is.
py::tuple seam_circles(Diagram& d, py::array_t<bool, py::array::c_style | py::array::forcecast> needed) {
    std::vector<std::optional<VoronoiCircleBox>> box;
    std::vector<char> shared, wide;
    locked(d, [&](Diagram& g) {  // the cache is the graph's: under its lock
        const std::vector<Ellipse>& s = *g.sites;
        const std::size_t m = g.faces.size();
        if (static_cast<std::size_t>(needed.size()) != m) throw py::value_error("needed: expected one flag a face");
        const bool* need = needed.data();
        box.resize(m);
        wide.assign(m, 0);
        auto set_box = [&](std::size_t k, const DoubleVoronoiCircle* doubles) {
            box[k] = voronoi_circle_box_any_width(s, g.faces[k], doubles);
            wide[k] = doubles && !is_tight(*box[k]);
        };
        auto certify = [&](std::size_t k) {
            if (box[k]) return;
            const auto& f = g.faces[k];
            const std::optional<DoubleVoronoiCircle> c = certify_voronoi_circle_in_doubles(s[f[0]], s[f[1]], s[f[2]], nullptr,
                                                                                      DoubleCertificate::tritangent_only);
            set_box(k, c ? &*c : nullptr);
        };
        auto tighten = [&](std::size_t k) {
            if (!wide[k]) return;
            box[k] = voronoi_circle_box(s, g.faces[k]);
            wide[k] = 0;
        };
        // Disjoint boxes, the wide ones tightened where they meet.
        auto boxes_differ = [&](std::size_t a, std::size_t b) {
            if (!circle_boxes_meet(*box[a], *box[b])) return true;
            if (!wide[a] && !wide[b]) return false;
            tighten(a), tighten(b);
            return !circle_boxes_meet(*box[a], *box[b]);
        };
        for (std::size_t k = 0; k < m; ++k) {
            const auto& f = g.faces[k];
            if (VoronoiCircle* cached = g.traits->cached_circle(f[0], f[1], f[2]))
                set_box(k, cached->in_doubles());
            else if (need[k])
                certify(k);
        }
        shared.assign(m, 0);
        const Triangulation& tds = g.graph->triangulation();
        // Per face without a box, its neighbours without one: of two such neighbours the one with more is
        // certified (on a chain of them, every other face).
        std::vector<std::uint8_t> open(m, 0);
        for (FaceIndex f : tds.faces()) {
            const long k = face_number(g.numbers, f);
            if (k < 0 || box[static_cast<std::size_t>(k)]) continue;
            for (int i = 0; i < 3; ++i) {
                const long j = face_number(g.numbers, tds.neighbor({f, i}));
                if (j >= 0 && !box[static_cast<std::size_t>(j)]) ++open[static_cast<std::size_t>(k)];
            }
        }
        for (FaceIndex f : tds.faces()) {
            const long k = face_number(g.numbers, f);
            if (k < 0) continue;
            for (int i = 0; i < 3; ++i) {
                const long j = face_number(g.numbers, tds.neighbor({f, i}));
                if (j <= k) continue;  // infinite, or the pair met from j
                const auto a = static_cast<std::size_t>(k), b = static_cast<std::size_t>(j);
                if (!box[a] && !box[b]) certify(open[a] >= open[b] ? a : b);
                bool differ = false;
                if (box[a] && box[b]) {
                    differ = boxes_differ(a, b);
                } else {
                    const std::size_t known = box[a] ? a : b, other = box[a] ? b : a;
                    differ = circle_differs_by_site(s, *box[known], g.faces[known], g.faces[other]);
                    if (!differ) {
                        certify(other);
                        differ = boxes_differ(a, b);
                    }
                }
                if (!differ) shared[a] = shared[b] = 1;
            }
        }
    });
    const auto m = static_cast<py::ssize_t>(box.size());
    auto boxes = new_array<double>({m, 6});
    auto may_share = new_array<bool>({m}), is_wide = new_array<bool>({m});
    double* out = boxes.mutable_data();
    bool* flag = may_share.mutable_data();
    bool* wide_out = is_wide.mutable_data();
    for (std::size_t k = 0; k < box.size(); ++k, out += 6) {
        if (box[k]) {
            const VoronoiCircleBox& c = *box[k];
            out[0] = c.center_x.lo, out[1] = c.center_x.hi, out[2] = c.center_y.lo, out[3] = c.center_y.hi;
            out[4] = c.radius.lo, out[5] = c.radius.hi;
        } else {
            std::fill_n(out, 6, std::numeric_limits<double>::quiet_NaN());
        }
        flag[k] = shared[k] != 0;
        wide_out[k] = wide[k] != 0;
    }
    return py::make_tuple(boxes, may_share, is_wide);
}

// Per face (in `faces` order) the numbers of the three faces across its
// edges, -1 for an infinite face: the triangulation's adjacency, which the
// tiled build's test for cocircular neighbours needs.
py::array_t<std::int64_t> face_neighbours(Diagram& d) {
    std::vector<std::int64_t> across;
    locked(d, [&](Diagram& g) {
        const Triangulation& tds = g.graph->triangulation();
        across.assign(3 * g.faces.size(), -1);
        for (FaceIndex f : tds.faces()) {
            const long k = face_number(g.numbers, f);
            if (k < 0) continue;
            for (int i = 0; i < 3; ++i) across[3 * static_cast<std::size_t>(k) + i] = face_number(g.numbers, tds.neighbor({f, i}));
        }
    });
    auto out = new_array<std::int64_t>({static_cast<py::ssize_t>(across.size() / 3), 3});
    std::copy(across.begin(), across.end(), out.mutable_data());
    return out;
}

py::dict vertex(Diagram& d, long i, long bits) {
    if (bits < 1 || bits > 10'000'000) throw py::value_error("bits: expected an integer in [1, 10^7]");
    const auto faces = locked(d, [](Diagram& g) { return g.faces; });
    const long n = static_cast<long>(faces.size());
    if (i < 0) i += n;
    if (i < 0 || i >= n) throw py::index_error("vertex index out of range");
    const std::array<SiteId, 3> f = faces[static_cast<std::size_t>(i)];
    const std::vector<Ellipse>& s = *d.sites;
    VoronoiCircleSolver solver(s[f[0]], s[f[1]], s[f[2]], common_medial_axis_tangency);
    {
        py::gil_scoped_release release;  // the sites never change: no lock needed
        solver.refine_existing(bits);    // a face has its counter-clockwise circle
    }
    py::dict out = enclosure_dict(solver.enclosure(), bits);
    out["face"] = py::make_tuple(f[0], f[1], f[2]);
    return out;
}

py::dict trace(Diagram& d, double tolerance, double margin) {
    if (!(tolerance > 0 && tolerance <= 1)) throw py::value_error("tolerance: expected a fraction in (0, 1]");
    if (!(margin >= 0 && margin <= 10)) throw py::value_error("margin: expected a fraction in [0, 10]");
    const TracedDiagram t =
        locked(d, [&](Diagram& g) { return trace_voronoi_diagram(*g.graph, *g.sites, tolerance, margin); });
    std::size_t total = 0;
    for (const VoronoiEdgeArc& a : t.arcs) total += a.points.size();
    const auto m = static_cast<py::ssize_t>(t.arcs.size());
    auto points = new_array<double>({static_cast<py::ssize_t>(total), 2});
    auto rho = new_array<double>({static_cast<py::ssize_t>(total)});
    auto offsets = new_array<std::int64_t>({m + 1});
    auto infinite = new_array<bool>({m, 2});
    std::vector<std::pair<SiteId, SiteId>> arc_sites;
    std::vector<std::pair<long, long>> arc_faces;
    auto p = points.mutable_unchecked<2>();
    auto r = rho.mutable_unchecked<1>();
    auto o = offsets.mutable_unchecked<1>();
    auto inf = infinite.mutable_unchecked<2>();
    auto number = [&](FaceIndex f) { return face_number(d.numbers, f); };
    py::ssize_t k = 0;
    for (py::ssize_t a = 0; a < m; ++a) {
        const VoronoiEdgeArc& arc = t.arcs[static_cast<std::size_t>(a)];
        o(a) = k;
        for (const BisectorPoint& b : arc.points) {
            p(k, 0) = b.x, p(k, 1) = b.y;
            r(k) = b.rho;
            ++k;
        }
        inf(a, 0) = arc.from_infinity, inf(a, 1) = arc.to_infinity;
        arc_sites.push_back({arc.p, arc.q});
        arc_faces.push_back({arc.from_infinity ? -1 : number(arc.left_face), arc.to_infinity ? -1 : number(arc.right_face)});
    }
    o(m) = k;
    py::dict out;
    out["points"] = points;
    out["rho"] = rho;
    out["offsets"] = offsets;
    out["sites"] = pairs_array(arc_sites);
    out["faces"] = pairs_array(arc_faces);
    out["infinite"] = infinite;
    out["box"] = py::make_tuple(t.box.xmin, t.box.ymin, t.box.xmax, t.box.ymax);
    out["tolerance"] = t.tolerance;
    out["failed_edges"] = t.failed_edges;
    out["misordered_edges"] = t.misordered_edges;
    return out;
}

std::string validate(Diagram& d, bool brute_force) {
    return locked(d, [&](Diagram& g) {
        std::string problem = g.graph->validate();
        if (problem.empty() && brute_force) problem = g.graph->brute_force_check();
        return problem;
    });
}

Sites diagram_sites(const Diagram& d) {
    Sites s;
    s.file = d.names;
    s.file.sites = *d.sites;
    s.from_file = d.from_file;
    return s;
}

}  // namespace

void bind_diagram(py::module_& m) {
    py::class_<Diagram, std::unique_ptr<Diagram>>(m, "_Diagram")
        .def_property_readonly("sites", &diagram_sites)
        .def_property_readonly("number_of_sites", [](const Diagram& d) { return d.sites->size(); })
        .def("hidden", [](Diagram& d) { return pairs_array(locked(d, [](Diagram& g) { return g.graph->hidden(); })); })
        .def("edges", [](Diagram& d) { return pairs_array(locked(d, [](Diagram& g) { return g.graph->edges(); })); })
        .def("faces", [](Diagram& d) { return faces_array(locked(d, [](Diagram& g) { return g.faces; })); })
        .def("hull", [](Diagram& d) { return pairs_array(locked(d, [](Diagram& g) { return g.graph->hull(); })); })
        .def("removed",
             [](Diagram& d) {
                 const std::vector<SiteId> r = locked(d, [](Diagram& g) { return g.graph->removed(); });
                 auto out = new_array<std::int64_t>({static_cast<py::ssize_t>(r.size())});
                 std::copy(r.begin(), r.end(), out.mutable_data());
                 return out;
             })
        .def("remove", &remove, py::arg("ids"))
        .def("ridges", &ridges)
        .def("vertices", &vertices)
        .def("regions", &regions)
        .def("json", &json)
        .def("stats_json", [](Diagram& d) { return locked(d, [](Diagram& g) { return g.stats; }); })
        .def("circle_boxes", &circle_boxes, py::arg("which") = py::none())
        .def("face_neighbours", &face_neighbours)
        .def("seam_circles", &seam_circles, py::arg("needed"))
        // The boxes of the graph's sites, as Sites._tiling_arrays gives them (a tile's worker makes them
        // rather than being sent them: python/ellvor/distributed.py).
        .def("_site_boxes", [](const Diagram& d) { return site_boxes(*d.sites); })
        .def("vertex", &vertex, py::arg("i"), py::arg("bits"))
        .def("trace", &trace, py::arg("tolerance"), py::arg("margin"))
        .def("validate", &validate, py::arg("brute_force"));

    m.def("_face_vertices", &face_vertices, py::arg("sites"), py::arg("faces"));
    m.def("_build", &build, py::arg("sites"), py::arg("fmt"), py::arg("progress"), py::arg("progress_interval"));
    // A tiled build's tile: its sites as numerator/denominator pairs (_sites_from_fractions), made and moved
    // to the graph's traits without a Sites object (that the traits would copy).
    m.def("_build_fractions", [](py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> fractions) {
        return build_graph(sites_from_fractions(fractions), py::none(), 0);
    }, py::arg("fractions"));
}

}  // namespace ellvor::python
