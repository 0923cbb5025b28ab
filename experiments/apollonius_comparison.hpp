// What the experiments compare between ellvor's Delaunay graph and CGAL's
// Apollonius graph on circles: the visible sites, the [hidden, hiding] pairs,
// the finite edges (a multiset of sorted pairs) and the hull, in ellvor's
// site ids; and the site generators of build_scaling's and overlap_scaling's sets.
#pragma once

#include "graph/delaunay_graph.hpp"
#include "sites/ellipse.hpp"
#include "sites/site_generators.hpp"

#include <CGAL/Apollonius_graph_2.h>
#include <CGAL/Apollonius_graph_filtered_traits_2.h>
#include <CGAL/Apollonius_graph_hierarchy_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace ellvor::experiments {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using AGTraits = CGAL::Apollonius_graph_filtered_traits_2<Kernel>;
using AG = CGAL::Apollonius_graph_2<AGTraits>;
using AGH = CGAL::Apollonius_graph_hierarchy_2<AGTraits>;
using Pairs = std::vector<std::pair<SiteId, SiteId>>;

struct Summary {
    std::vector<SiteId> visible;
    Pairs hidden, edges, hull;
};

inline Summary summary_of(const DelaunayGraph& g) {
    Summary s{g.visible_sites(), g.hidden(), g.edges(), {}};
    if (s.visible.size() >= 3) s.hull = g.hull();
    return s;
}

// The circles as CGAL sites (exact for the dyadic circles of the sets below).
inline std::vector<AG::Site_2> cgal_sites(const std::vector<Ellipse>& sites) {
    std::vector<AG::Site_2> input;
    for (const Ellipse& e : sites)
        input.push_back(AG::Site_2(AG::Point_2(e.xc().to_double(), e.yc().to_double()), e.a().to_double()));
    return input;
}

// Site ids of CGAL sites, by their exact double data.
class CgalSiteIds {
public:
    explicit CgalSiteIds(const std::vector<AG::Site_2>& input) {
        for (SiteId i = 0; i < input.size(); ++i) id_[{input[i].point().x(), input[i].point().y(), input[i].weight()}] = i;
    }
    SiteId operator()(const AG::Site_2& s) const {
        return id_.at({CGAL::to_double(s.point().x()), CGAL::to_double(s.point().y()), CGAL::to_double(s.weight())});
    }

private:
    std::map<std::tuple<double, double, double>, SiteId> id_;
};

// CGAL's graph (Graph: AG or AGH) in ellvor's ids.
template <class Graph>
Summary summary_of(const Graph& ag, const CgalSiteIds& site_id) {
    Summary out;
    for (auto v = ag.finite_vertices_begin(); v != ag.finite_vertices_end(); ++v) {
        out.visible.push_back(site_id(v->site()));
        for (auto h = v->hidden_sites_begin(); h != v->hidden_sites_end(); ++h)
            out.hidden.push_back({site_id(*h), site_id(v->site())});
    }
    for (auto e = ag.finite_edges_begin(); e != ag.finite_edges_end(); ++e) {
        const SiteId a = site_id(e->first->vertex(ccw(e->second))->site());
        const SiteId b = site_id(e->first->vertex(cw(e->second))->site());
        out.edges.push_back({std::min(a, b), std::max(a, b)});
    }
    if (ag.number_of_vertices() >= 3)
        for (auto f = ag.all_faces_begin(); f != ag.all_faces_end(); ++f) {
            if (!ag.is_infinite(f)) continue;
            const int k = f->index(ag.infinite_vertex());
            out.hull.push_back({site_id(f->vertex(ccw(k))->site()), site_id(f->vertex(cw(k))->site())});
        }
    std::sort(out.visible.begin(), out.visible.end());
    std::sort(out.hidden.begin(), out.hidden.end());
    std::sort(out.edges.begin(), out.edges.end());
    std::sort(out.hull.begin(), out.hull.end());
    return out;
}

// "ok", or what differs.
inline std::string compare(const Summary& a, const Summary& b) {
    std::string out;
    if (a.visible != b.visible) out += "visible sites differ; ";
    if (a.hidden != b.hidden) out += "hidden pairs differ; ";
    if (a.edges != b.edges)
        out += "edges differ (" + std::to_string(a.edges.size()) + " vs " + std::to_string(b.edges.size()) + "); ";
    if (a.hull != b.hull) out += "hull differs; ";
    return out.empty() ? "ok" : out;
}

// build_scaling's sets: "circles" (dyadic, exact in double), "ellipses",
// "ellipses-nest10" (nested fraction 1/10); overlap_scaling's "circles-cross30":
// "circles" with crossing fraction 3/10 (the same grid and radii), and
// "ellipses-cross30": "ellipses" with crossing fraction 3/10 (`ellvor generate
// ellipses --count n --seed S --crossing 0.3`). Seed 1 unless told.
inline std::vector<Ellipse> make_sites(const std::string& set, long n, std::uint64_t seed = 1) {
    GeneratorOptions o;
    o.count = n;
    o.seed = seed;
    if (set == "circles" || set == "circles-cross30") {
        o.kind = SiteKind::circles;
        o.bits = 1;
        o.box = Rational(256 * static_cast<long>(std::ceil(std::sqrt(double(n)) - 1e-9)));
        if (set == "circles-cross30") o.crossing_fraction = Rational(3, 10);
    } else {
        o.kind = SiteKind::ellipses;
        o.bits = 8;
        o.box = Rational(100);
        if (set == "ellipses-nest10") o.nested_fraction = Rational(1, 10);
        if (set == "ellipses-cross30") o.crossing_fraction = Rational(3, 10);
    }
    return generate_sites(o);
}

inline std::string describe_set(const std::string& set) {
    if (set == "circles") return "generate_sites(circles, seed 1, bits 1, box 256 ceil(sqrt n)) — dyadic, exact in double";
    if (set == "circles-cross30")
        return "generate_sites(circles, seed 1, bits 1, box 256 ceil(sqrt n), crossing fraction 3/10) — dyadic, exact "
               "in double";
    if (set == "ellipses-cross30") return "generate_sites(ellipses, seed 1, bits 8, box 100, crossing fraction 3/10)";
    if (set == "ellipses-nest10") return "generate_sites(ellipses, seed 1, bits 8, box 100, nested fraction 1/10)";
    return "generate_sites(ellipses, seed 1, bits 8, box 100)";
}

}  // namespace ellvor::experiments
