#include "output/svg_writer.hpp"

#include "output/color_scale.hpp"
#include "output/packing_fraction.hpp"
#include "predicates/relative_position.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace ellvor {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string num(double x) {
    if (x == 0 || !std::isfinite(x)) return "0";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.7g", x);
    return buffer;
}

std::string escape(const std::string& s) {
    std::string out;
    for (char ch : s) {
        switch (ch) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += ch;
        }
    }
    return out;
}

// Colours.
const char* const kSiteFill = "#dbe8f5";
const char* const kSiteStroke = "#1f4e79";
const char* const kHiddenStroke = "#9a9a9a";
const char* const kDelaunay = "#7fb77e";
const char* const kVoronoi = "#c0392b";
const char* const kVertex = "#7b1b12";
// Overlaps: the site stroke's colour, translucent, so that a region covered
// by k sites, shaded once per pair, darkens with k, and the boundary under it
// shows through.
const char* const kOverlapFill = kSiteStroke;
const char* const kOverlapOpacity = "0.25";

// The visible sites whose boundaries cross, as first -> the later ones (i < j):
// bounding boxes swept along x, then relative_position decides each pair whose
// boxes meet.
std::map<SiteId, std::vector<SiteId>> crossing_pairs(const std::vector<Ellipse>& sites, const std::set<SiteId>& hidden) {
    struct Box {
        SiteId id;
        double xmin, xmax, ymin, ymax;
    };
    std::vector<Box> boxes;
    for (SiteId i = 0; i < sites.size(); ++i) {
        if (hidden.count(i)) continue;
        const EllipseShape e = EllipseShape::of(sites[i]);
        const double w = e.half_width(), h = e.half_height();
        boxes.push_back({i, e.xc - w, e.xc + w, e.yc - h, e.yc + h});
    }
    std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) { return a.xmin < b.xmin; });
    std::map<SiteId, std::vector<SiteId>> pairs;
    for (std::size_t k = 0; k < boxes.size(); ++k)
        for (std::size_t l = k + 1; l < boxes.size() && boxes[l].xmin <= boxes[k].xmax; ++l) {
            const Box &a = boxes[k], &b = boxes[l];
            if (b.ymin > a.ymax || a.ymin > b.ymax) continue;
            if (*relative_position(sites[a.id], sites[b.id]) != RelativePosition::intersecting) continue;
            pairs[std::min(a.id, b.id)].push_back(std::max(a.id, b.id));
        }
    for (auto& [i, later] : pairs) std::sort(later.begin(), later.end());
    return pairs;
}

// Where the drawing goes on the page: the world's scale and offset (y up),
// the legend's place and the page's size, in pixels.
struct PageLayout {
    double s = 1;  // pixels per world unit
    double pad = 20, top = 48, legend_width = 250;
    double legend_x = 0, legend_h = 0, width = 0, height = 0;
    double tx = 0, ty = 0;  // the world's origin on the page

    double px(double pixels) const { return pixels / s; }  // a length of `pixels` pixels in world units
    double screen_x(double x) const { return tx + s * x; }
    double screen_y(double y) const { return ty - s * y; }
};

// The colour of each site's cell: the midpoint of its packing fraction on
// the scale [lo, hi] of the bounded cells' values; NaN where not coloured.
struct CellColors {
    std::vector<double> value;  // per site
    double lo = 0, hi = 0;
    bool rings = false;         // the cells have rings (else the sites are filled)
    std::size_t colored = 0;

    explicit CellColors(const CellTessellation* cells) {
        if (!cells) return;
        lo = HUGE_VAL, hi = -HUGE_VAL;
        bool every_ring = true;
        for (const Cell& c : cells->cells) {
            const std::optional<Ball> f = c.bounded ? packing_fraction(c) : std::nullopt;
            value.push_back(f && arb_is_finite(f->get()) ? f->mid_double() : NAN);
            if (std::isnan(value.back())) continue;
            ++colored;
            lo = std::min(lo, value.back());
            hi = std::max(hi, value.back());
            every_ring = every_ring && !c.ring.empty();
        }
        rings = colored > 0 && every_ring;
        if (colored == 0) lo = 0, hi = 1;
        if (hi <= lo) hi = lo + 1e-9 * std::max(1.0, std::fabs(lo));
    }
    bool active() const { return !value.empty(); }
    bool has(SiteId i) const { return i < value.size() && !std::isnan(value[i]); }
    std::string color(SiteId i) const { return sequential_color((value[i] - lo) / (hi - lo)); }
};

PageLayout page_layout(const DrawingBox& box, const SvgOptions& o, bool has_overlaps, bool has_failed_edges) {
    PageLayout l;
    l.s = o.pixels / box.size();
    const double draw_w = l.s * box.width(), draw_h = l.s * box.height();
    l.legend_x = l.pad + draw_w + l.pad;
    l.legend_h = 22 + (has_overlaps ? 6 : 5) * 24 + 14 + (has_failed_edges ? 18 : 0) + (o.cells ? 96 : 0);
    l.width = l.legend_x + l.legend_width;
    l.height = std::max(l.top + draw_h + l.pad, l.top + l.legend_h + l.pad);
    l.tx = l.pad - l.s * box.xmin;
    l.ty = l.top + l.s * box.ymax;
    return l;
}

// One SVG page of a traced diagram, written part by part in document order.
class SvgPage {
public:
    SvgPage(std::ostream& out, const DelaunayGraph& graph, const std::vector<Ellipse>& sites, const TracedDiagram& d,
            const SvgOptions& o)
        : out_(out), sites_(sites), d_(d), o_(o), edges_(graph.edges()), vertex_count_(graph.faces().size()),
          colors_(o.cells) {
        const auto hidden = graph.hidden();
        hidden_count_ = hidden.size();
        for (const auto& h : hidden) hidden_ids_.insert(h.first);
        crossing_ = crossing_pairs(sites, hidden_ids_);
        for (const auto& [i, later] : crossing_) overlaps_ += later.size();
        layout_ = page_layout(d.box, o, overlaps_ > 0, d.failed_edges > 0);
        title_ = o.title.empty() ? "Voronoi diagram of " + std::to_string(sites.size()) + " ellipses" : o.title;
    }

    void write() {
        header();
        defs();
        background_and_title();
        world();
        if (o_.show_ids) site_ids();
        legend();
        out_ << "</svg>\n";
    }

private:
    std::ostream& out_;
    const std::vector<Ellipse>& sites_;
    const TracedDiagram& d_;
    const SvgOptions& o_;
    const std::vector<std::pair<SiteId, SiteId>> edges_;
    const std::size_t vertex_count_;
    std::size_t hidden_count_ = 0;
    std::set<SiteId> hidden_ids_;
    std::map<SiteId, std::vector<SiteId>> crossing_;
    std::size_t overlaps_ = 0;
    PageLayout layout_;
    std::string title_;
    CellColors colors_;

    // An ellipse element's geometry (world coordinates).
    std::string geometry(SiteId i) const {
        const EllipseShape e = EllipseShape::of(sites_[i]);
        const double degrees = std::atan2(e.s, e.c) * 180 / kPi;
        std::string g = " cx=\"" + num(e.xc) + "\" cy=\"" + num(e.yc) + "\" rx=\"" + num(e.a) + "\" ry=\"" + num(e.b) + "\"";
        if (degrees != 0) g += " transform=\"rotate(" + num(degrees) + " " + num(e.xc) + " " + num(e.yc) + ")\"";
        return g;
    }

    void header() {
        const DrawingBox& box = d_.box;
        out_ << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
        out_ << "<!-- ellvor: Voronoi diagram of ellipses (floating-point drawing). Voronoi edges are traced\n"
                "     bisector arcs: every point is equidistant from its two sites up to a floating-point\n"
                "     root solve (~1e-12 relative); consecutive points are closer than the tolerance "
             << num(d_.tolerance) << "\n     (" << num(100 * o_.tolerance_fraction)
             << "% of the drawing box's larger side). Drawing box: [" << num(box.xmin) << ", " << num(box.xmax)
             << "] x [" << num(box.ymin) << ", " << num(box.ymax) << "]; y points up. -->\n";
        out_ << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(layout_.width) << "\" height=\""
             << num(layout_.height) << "\" viewBox=\"0 0 " << num(layout_.width) << " " << num(layout_.height)
             << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n";
        out_ << "<title>" << escape(title_) << "</title>\n";
    }

    // The drawing box's clip and, for each site that crosses later ones, its
    // outline as a clip of those.
    void defs() {
        const DrawingBox& box = d_.box;
        out_ << "<defs><clipPath id=\"drawing-box\"><rect x=\"" << num(box.xmin) << "\" y=\"" << num(box.ymin)
             << "\" width=\"" << num(box.width()) << "\" height=\"" << num(box.height()) << "\"/></clipPath>";
        for (const auto& [i, later] : crossing_)
            out_ << "\n<clipPath id=\"site-" << i << "\"><ellipse" << geometry(i) << "/></clipPath>";
        out_ << "</defs>\n";
    }

    void background_and_title() {
        out_ << "<rect x=\"0\" y=\"0\" width=\"" << num(layout_.width) << "\" height=\"" << num(layout_.height)
             << "\" fill=\"white\"/>\n";
        out_ << "<text x=\"" << num(layout_.pad) << "\" y=\"30\" font-size=\"18\" font-weight=\"bold\" fill=\"#222\">"
             << escape(title_) << "</text>\n";
    }

    // Everything in world coordinates (y up), clipped to the drawing box.
    void world() {
        const DrawingBox& box = d_.box;
        out_ << "<g id=\"world\" transform=\"matrix(" << num(layout_.s) << " 0 0 " << num(-layout_.s) << " "
             << num(layout_.tx) << " " << num(layout_.ty) << ")\">\n";
        out_ << "<rect x=\"" << num(box.xmin) << "\" y=\"" << num(box.ymin) << "\" width=\"" << num(box.width())
             << "\" height=\"" << num(box.height()) << "\" fill=\"#fcfcfa\" stroke=\"#bbbbbb\" stroke-width=\""
             << num(layout_.px(1)) << "\"/>\n";
        out_ << "<g clip-path=\"url(#drawing-box)\">\n";
        if (colors_.rings) cell_fills();
        sites();
        delaunay_edges();
        voronoi_edges();
        voronoi_vertices();
        out_ << "</g>\n</g>\n";  // clip, world
    }

    void ellipse(SiteId i, bool is_hidden) {
        out_ << "<ellipse data-site=\"" << i << "\"" << geometry(i);
        if (is_hidden)
            out_ << " fill=\"none\" stroke=\"" << kHiddenStroke << "\" stroke-width=\"" << num(layout_.px(1.1))
                 << "\" stroke-dasharray=\"" << num(layout_.px(4)) << " " << num(layout_.px(3)) << "\"/>\n";
        else
            out_ << " fill=\"" << (colors_.active() && !colors_.rings && colors_.has(i) ? colors_.color(i) : kSiteFill)
                 << "\" stroke=\"" << kSiteStroke << "\" stroke-width=\"" << num(layout_.px(1.3)) << "\"/>\n";
    }

    // The visible sites, the lenses of crossing pairs, the hidden sites.
    void sites() {
        out_ << "<g id=\"sites\">\n";
        for (SiteId i = 0; i < sites_.size(); ++i)
            if (!hidden_ids_.count(i)) ellipse(i, false);
        out_ << "</g>\n";
        if (overlaps_ > 0) {
            // The lens of each crossing pair: the later site clipped to the
            // earlier (the clip in a <g>: on the ellipse it would be rotated with it).
            out_ << "<g id=\"overlaps\" fill=\"" << kOverlapFill << "\" fill-opacity=\"" << kOverlapOpacity << "\">\n";
            for (const auto& [i, later] : crossing_) {
                out_ << "<g clip-path=\"url(#site-" << i << ")\">";
                for (SiteId j : later) out_ << "<ellipse data-sites=\"" << i << " " << j << "\"" << geometry(j) << "/>";
                out_ << "</g>\n";
            }
            out_ << "</g>\n";
        }
        out_ << "<g id=\"hidden-sites\">\n";
        for (SiteId i : hidden_ids_) ellipse(i, true);
        out_ << "</g>\n";
    }

    // Each coloured cell's ring, filled (under the sites).
    void cell_fills() {
        out_ << "<g id=\"cell-fills\" stroke=\"none\">\n";
        for (SiteId i = 0; i < sites_.size(); ++i) {
            if (!colors_.has(i)) continue;
            out_ << "<polygon data-site=\"" << i << "\" data-packing-fraction=\"" << num(colors_.value[i]) << "\" fill=\""
                 << colors_.color(i) << "\" points=\"";
            const auto& ring = o_.cells->cells[i].ring;
            for (std::size_t k = 0; k < ring.size(); ++k) out_ << (k ? " " : "") << num(ring[k][0]) << "," << num(ring[k][1]);
            out_ << "\"/>\n";
        }
        out_ << "</g>\n";
    }

    // The colour bar: the scale from the smallest to the largest value shown.
    void color_bar(double lx, double& row) {
        const double x = lx + 10, w = layout_.legend_width - layout_.pad - 20;
        out_ << "<g id=\"color-bar\" data-colored-cells=\"" << colors_.colored << "\" data-rings=\""
             << (colors_.rings ? "yes" : "no") << "\">\n";
        out_ << "<text x=\"" << num(x) << "\" y=\"" << num(row + 4) << "\" font-size=\"12\">local packing fraction</text>\n";
        row += 10;
        const int steps = 32;
        for (int k = 0; k < steps; ++k)
            out_ << "<rect x=\"" << num(x + w * k / steps) << "\" y=\"" << num(row) << "\" width=\"" << num(w / steps + 0.5)
                 << "\" height=\"12\" fill=\"" << sequential_color((k + 0.5) / steps) << "\"/>\n";
        row += 24;
        out_ << "<text x=\"" << num(x) << "\" y=\"" << num(row) << "\" font-size=\"11\">" << num(colors_.lo)
             << "</text><text x=\"" << num(x + w) << "\" y=\"" << num(row) << "\" font-size=\"11\" text-anchor=\"end\">"
             << num(colors_.hi) << "</text>\n";
        row += 16;
        out_ << "<text x=\"" << num(x) << "\" y=\"" << num(row) << "\" font-size=\"10\" fill=\"#555\">"
             << "interval midpoints, " << colors_.colored << " bounded cells" << "</text>\n";
        row += 14;
        out_ << "<text x=\"" << num(x) << "\" y=\"" << num(row) << "\" font-size=\"10\" fill=\"#555\">"
             << (colors_.rings ? "cells filled; unbounded ones blank" : "no cell rings yet: sites filled") << "</text>\n";
        row += 18;
        out_ << "</g>\n";
    }

    void delaunay_edges() {
        out_ << "<g id=\"delaunay-edges\" stroke=\"" << kDelaunay << "\" stroke-width=\"" << num(layout_.px(0.8))
             << "\" stroke-opacity=\"0.8\" stroke-dasharray=\"" << num(layout_.px(5)) << " " << num(layout_.px(3))
             << "\">\n";
        for (const auto& [i, j] : edges_) {
            const EllipseShape a = EllipseShape::of(sites_[i]), b = EllipseShape::of(sites_[j]);
            out_ << "<line x1=\"" << num(a.xc) << "\" y1=\"" << num(a.yc) << "\" x2=\"" << num(b.xc) << "\" y2=\""
                 << num(b.yc) << "\"/>\n";
        }
        out_ << "</g>\n";
    }

    void voronoi_edges() {
        out_ << "<g id=\"voronoi-edges\" fill=\"none\" stroke=\"" << kVoronoi << "\" stroke-width=\""
             << num(layout_.px(1.6)) << "\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
        for (const VoronoiEdgeArc& arc : d_.arcs) {
            out_ << "<path data-sites=\"" << arc.p << " " << arc.q << "\" d=\"";
            for (std::size_t k = 0; k < arc.points.size(); ++k)
                out_ << (k == 0 ? "M" : k == 1 ? " L" : " ") << num(arc.points[k].x) << " " << num(arc.points[k].y);
            out_ << "\"/>\n";
        }
        out_ << "</g>\n";
    }

    void voronoi_vertices() {
        out_ << "<g id=\"voronoi-vertices\" fill=\"" << kVertex << "\">\n";
        for (const VoronoiVertexPoint& v : d_.vertices)
            if (v.certified && d_.box.contains(v.x, v.y))
                out_ << "<circle cx=\"" << num(v.x) << "\" cy=\"" << num(v.y) << "\" r=\"" << num(layout_.px(2.4))
                     << "\"/>\n";
        out_ << "</g>\n";
    }

    // Each site's id at its center, in page coordinates; a hidden site's a
    // line lower (its host's id is often at the same place).
    void site_ids() {
        out_ << "<g id=\"site-ids\" font-size=\"11\" text-anchor=\"middle\" dominant-baseline=\"central\" "
                "stroke=\"white\" stroke-width=\"3\" stroke-opacity=\"0.8\" paint-order=\"stroke\">\n";
        for (SiteId i = 0; i < sites_.size(); ++i) {
            const EllipseShape e = EllipseShape::of(sites_[i]);
            const bool h = hidden_ids_.count(i) != 0;
            out_ << "<text x=\"" << num(layout_.screen_x(e.xc)) << "\" y=\"" << num(layout_.screen_y(e.yc) + (h ? 12 : 0))
                 << "\" fill=\"" << (h ? "#777777" : "#0d2a47") << "\"" << (h ? " font-style=\"italic\"" : "") << ">"
                 << i << "</text>\n";
        }
        out_ << "</g>\n";
    }

    // The legend: one sample and count per kind of mark, then the tolerance.
    void legend() {
        out_ << "<g id=\"legend\" data-sites=\"" << sites_.size() << "\" data-hidden=\"" << hidden_count_
             << "\" data-delaunay-edges=\"" << edges_.size() << "\" data-voronoi-vertices=\"" << vertex_count_
             << "\" data-voronoi-edges=\"" << d_.arcs.size() << "\" data-overlaps=\"" << overlaps_
             << "\" font-size=\"13\" fill=\"#222\">\n";
        const double lx = layout_.legend_x, ly = layout_.top;
        out_ << "<rect x=\"" << num(lx) << "\" y=\"" << num(ly) << "\" width=\"" << num(layout_.legend_width - layout_.pad)
             << "\" height=\"" << num(layout_.legend_h) << "\" fill=\"white\" stroke=\"#cccccc\"/>\n";
        double row = ly + 22;
        auto text = [&](const std::string& t) {
            out_ << "<text x=\"" << num(lx + 44) << "\" y=\"" << num(row + 4) << "\">" << escape(t) << "</text>\n";
            row += 24;
        };
        const double sx = lx + 10, ex = lx + 34;
        out_ << "<rect x=\"" << num(sx) << "\" y=\"" << num(row - 7) << "\" width=\"24\" height=\"14\" rx=\"7\" fill=\""
             << kSiteFill << "\" stroke=\"" << kSiteStroke << "\" stroke-width=\"1.3\"/>\n";
        text("sites: " + std::to_string(sites_.size()));
        out_ << "<rect x=\"" << num(sx) << "\" y=\"" << num(row - 7)
             << "\" width=\"24\" height=\"14\" rx=\"7\" fill=\"none\" stroke=\"" << kHiddenStroke
             << "\" stroke-width=\"1.1\" stroke-dasharray=\"4 3\"/>\n";
        text("hidden: " + std::to_string(hidden_count_));
        if (overlaps_ > 0) {
            out_ << "<rect x=\"" << num(sx) << "\" y=\"" << num(row - 7) << "\" width=\"24\" height=\"14\" fill=\""
                 << kSiteFill << "\"/>\n<rect x=\"" << num(sx) << "\" y=\"" << num(row - 7)
                 << "\" width=\"24\" height=\"14\" fill=\"" << kOverlapFill << "\" fill-opacity=\"" << kOverlapOpacity
                 << "\"/>\n";
            text("overlapping pairs: " + std::to_string(overlaps_));
        }
        out_ << "<line x1=\"" << num(sx) << "\" y1=\"" << num(row) << "\" x2=\"" << num(ex) << "\" y2=\"" << num(row)
             << "\" stroke=\"" << kDelaunay << "\" stroke-width=\"1\" stroke-dasharray=\"5 3\"/>\n";
        text("Delaunay edges: " + std::to_string(edges_.size()));
        out_ << "<line x1=\"" << num(sx) << "\" y1=\"" << num(row) << "\" x2=\"" << num(ex) << "\" y2=\"" << num(row)
             << "\" stroke=\"" << kVoronoi << "\" stroke-width=\"2\"/>\n";
        text("Voronoi edges: " + std::to_string(d_.arcs.size()));
        out_ << "<circle cx=\"" << num(0.5 * (sx + ex)) << "\" cy=\"" << num(row) << "\" r=\"3\" fill=\"" << kVertex
             << "\"/>\n";
        text("Voronoi vertices: " + std::to_string(vertex_count_));
        out_ << "<text x=\"" << num(lx + 10) << "\" y=\"" << num(row + 4)
             << "\" font-size=\"11\" fill=\"#555\">arc tolerance " << num(d_.tolerance) << " ("
             << num(100 * o_.tolerance_fraction) << "% of box)</text>\n";
        row += 18;
        if (colors_.active()) color_bar(lx, row);
        if (d_.failed_edges > 0)
            out_ << "<text x=\"" << num(lx + 10) << "\" y=\"" << num(row + 4) << "\" font-size=\"11\" fill=\"#b00\">"
                 << d_.failed_edges << " edge(s) not drawn (uncertified vertex)</text>\n";
        out_ << "</g>\n";
    }
};

}  // namespace

void render_svg(std::ostream& out, const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                const TracedDiagram& d, const SvgOptions& o) {
    SvgPage(out, graph, sites, d, o).write();
}

TracedDiagram write_svg(std::ostream& out, const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                        const SvgOptions& options) {
    const TracedDiagram d = trace_voronoi_diagram(graph, sites, options.tolerance_fraction, options.margin_fraction);
    render_svg(out, graph, sites, d, options);
    return d;
}

}  // namespace ellvor
