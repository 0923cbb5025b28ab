#include "output/svg_writer.hpp"

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

}  // namespace

void render_svg(std::ostream& out, const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                const TracedDiagram& d, const SvgOptions& o) {
    const auto edges = graph.edges();
    const auto faces = graph.faces();
    const auto hidden = graph.hidden();
    std::set<SiteId> hidden_ids;
    for (const auto& h : hidden) hidden_ids.insert(h.first);
    const std::map<SiteId, std::vector<SiteId>> crossing = crossing_pairs(sites, hidden_ids);
    std::size_t overlaps = 0;
    for (const auto& [i, later] : crossing) overlaps += later.size();

    const DrawingBox& box = d.box;
    const double s = o.pixels / box.size();           // pixels per world unit
    const double pad = 20, top = 48, legend_width = 250;
    const double draw_w = s * box.width(), draw_h = s * box.height();
    const double legend_x = pad + draw_w + pad;
    const double legend_h = 22 + (overlaps > 0 ? 6 : 5) * 24 + 14 + (d.failed_edges > 0 ? 18 : 0);
    const double width = legend_x + legend_width;
    const double height = std::max(top + draw_h + pad, top + legend_h + pad);
    const double tx = pad - s * box.xmin, ty = top + s * box.ymax;
    auto px = [&](double world) { return world / s; };  // a length of `world` pixels in world units
    auto screen_x = [&](double x) { return tx + s * x; };
    auto screen_y = [&](double y) { return ty - s * y; };

    const std::string title =
        o.title.empty() ? "Voronoi diagram of " + std::to_string(sites.size()) + " ellipses" : o.title;

    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out << "<!-- ellvor: Voronoi diagram of ellipses (floating-point drawing). Voronoi edges are traced\n"
           "     bisector arcs: every point is equidistant from its two sites up to a floating-point\n"
           "     root solve (~1e-12 relative); consecutive points are closer than the tolerance "
        << num(d.tolerance) << "\n     (" << num(100 * o.tolerance_fraction)
        << "% of the drawing box's larger side). Drawing box: [" << num(box.xmin) << ", " << num(box.xmax) << "] x ["
        << num(box.ymin) << ", " << num(box.ymax) << "]; y points up. -->\n";
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
        << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n";
    out << "<title>" << escape(title) << "</title>\n";
    // An ellipse element's geometry (world coordinates).
    auto geometry = [&](SiteId i) {
        const EllipseShape e = EllipseShape::of(sites[i]);
        const double degrees = std::atan2(e.s, e.c) * 180 / kPi;
        std::string g = " cx=\"" + num(e.xc) + "\" cy=\"" + num(e.yc) + "\" rx=\"" + num(e.a) + "\" ry=\"" + num(e.b) + "\"";
        if (degrees != 0) g += " transform=\"rotate(" + num(degrees) + " " + num(e.xc) + " " + num(e.yc) + ")\"";
        return g;
    };
    out << "<defs><clipPath id=\"drawing-box\"><rect x=\"" << num(box.xmin) << "\" y=\"" << num(box.ymin)
        << "\" width=\"" << num(box.width()) << "\" height=\"" << num(box.height()) << "\"/></clipPath>";
    // Each site that crosses a later one clips the later ones to itself.
    for (const auto& [i, later] : crossing) out << "\n<clipPath id=\"site-" << i << "\"><ellipse" << geometry(i) << "/></clipPath>";
    out << "</defs>\n";
    out << "<rect x=\"0\" y=\"0\" width=\"" << num(width) << "\" height=\"" << num(height) << "\" fill=\"white\"/>\n";
    out << "<text x=\"" << num(pad) << "\" y=\"30\" font-size=\"18\" font-weight=\"bold\" fill=\"#222\">" << escape(title)
        << "</text>\n";

    // The world, y up.
    out << "<g id=\"world\" transform=\"matrix(" << num(s) << " 0 0 " << num(-s) << " " << num(tx) << " " << num(ty)
        << ")\">\n";
    out << "<rect x=\"" << num(box.xmin) << "\" y=\"" << num(box.ymin) << "\" width=\"" << num(box.width())
        << "\" height=\"" << num(box.height()) << "\" fill=\"#fcfcfa\" stroke=\"#bbbbbb\" stroke-width=\"" << num(px(1))
        << "\"/>\n";
    out << "<g clip-path=\"url(#drawing-box)\">\n";

    auto ellipse = [&](SiteId i, bool is_hidden) {
        out << "<ellipse data-site=\"" << i << "\"" << geometry(i);
        if (is_hidden)
            out << " fill=\"none\" stroke=\"" << kHiddenStroke << "\" stroke-width=\"" << num(px(1.1))
                << "\" stroke-dasharray=\"" << num(px(4)) << " " << num(px(3)) << "\"/>\n";
        else
            out << " fill=\"" << kSiteFill << "\" stroke=\"" << kSiteStroke << "\" stroke-width=\"" << num(px(1.3))
                << "\"/>\n";
    };
    out << "<g id=\"sites\">\n";
    for (SiteId i = 0; i < sites.size(); ++i)
        if (!hidden_ids.count(i)) ellipse(i, false);
    out << "</g>\n";
    if (overlaps > 0) {
        // The lens of each crossing pair: the later site clipped to the
        // earlier (the clip in a <g>: on the ellipse it would be rotated with it).
        out << "<g id=\"overlaps\" fill=\"" << kOverlapFill << "\" fill-opacity=\"" << kOverlapOpacity << "\">\n";
        for (const auto& [i, later] : crossing) {
            out << "<g clip-path=\"url(#site-" << i << ")\">";
            for (SiteId j : later) out << "<ellipse data-sites=\"" << i << " " << j << "\"" << geometry(j) << "/>";
            out << "</g>\n";
        }
        out << "</g>\n";
    }
    out << "<g id=\"hidden-sites\">\n";
    for (SiteId i : hidden_ids) ellipse(i, true);
    out << "</g>\n";

    out << "<g id=\"delaunay-edges\" stroke=\"" << kDelaunay << "\" stroke-width=\"" << num(px(0.8))
        << "\" stroke-opacity=\"0.8\" stroke-dasharray=\"" << num(px(5)) << " " << num(px(3)) << "\">\n";
    for (const auto& [i, j] : edges) {
        const EllipseShape a = EllipseShape::of(sites[i]), b = EllipseShape::of(sites[j]);
        out << "<line x1=\"" << num(a.xc) << "\" y1=\"" << num(a.yc) << "\" x2=\"" << num(b.xc) << "\" y2=\"" << num(b.yc)
            << "\"/>\n";
    }
    out << "</g>\n";

    out << "<g id=\"voronoi-edges\" fill=\"none\" stroke=\"" << kVoronoi << "\" stroke-width=\"" << num(px(1.6))
        << "\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
    for (const VoronoiEdgeArc& arc : d.arcs) {
        out << "<path data-sites=\"" << arc.p << " " << arc.q << "\" d=\"";
        for (std::size_t k = 0; k < arc.points.size(); ++k)
            out << (k == 0 ? "M" : k == 1 ? " L" : " ") << num(arc.points[k].x) << " " << num(arc.points[k].y);
        out << "\"/>\n";
    }
    out << "</g>\n";

    out << "<g id=\"voronoi-vertices\" fill=\"" << kVertex << "\">\n";
    for (const VoronoiVertexPoint& v : d.vertices)
        if (v.certified && box.contains(v.x, v.y))
            out << "<circle cx=\"" << num(v.x) << "\" cy=\"" << num(v.y) << "\" r=\"" << num(px(2.4)) << "\"/>\n";
    out << "</g>\n";
    out << "</g>\n</g>\n";  // clip, world

    if (o.show_ids) {
        // Hidden sites' ids a line below their center (their host's id is often at the same place).
        out << "<g id=\"site-ids\" font-size=\"11\" text-anchor=\"middle\" dominant-baseline=\"central\" "
               "stroke=\"white\" stroke-width=\"3\" stroke-opacity=\"0.8\" paint-order=\"stroke\">\n";
        for (SiteId i = 0; i < sites.size(); ++i) {
            const EllipseShape e = EllipseShape::of(sites[i]);
            const bool h = hidden_ids.count(i) != 0;
            out << "<text x=\"" << num(screen_x(e.xc)) << "\" y=\"" << num(screen_y(e.yc) + (h ? 12 : 0)) << "\" fill=\""
                << (h ? "#777777" : "#0d2a47") << "\"" << (h ? " font-style=\"italic\"" : "") << ">" << i << "</text>\n";
        }
        out << "</g>\n";
    }

    // Legend.
    out << "<g id=\"legend\" data-sites=\"" << sites.size() << "\" data-hidden=\"" << hidden.size()
        << "\" data-delaunay-edges=\"" << edges.size() << "\" data-voronoi-vertices=\"" << faces.size()
        << "\" data-voronoi-edges=\"" << d.arcs.size() << "\" data-overlaps=\"" << overlaps << "\" font-size=\"13\" fill=\"#222\">\n";
    const double lx = legend_x, ly = top;
    out << "<rect x=\"" << num(lx) << "\" y=\"" << num(ly) << "\" width=\"" << num(legend_width - pad) << "\" height=\""
        << num(legend_h) << "\" fill=\"white\" stroke=\"#cccccc\"/>\n";
    double row = ly + 22;
    auto text = [&](const std::string& t) {
        out << "<text x=\"" << num(lx + 44) << "\" y=\"" << num(row + 4) << "\">" << escape(t) << "</text>\n";
        row += 24;
    };
    const double sx = lx + 10, ex = lx + 34;
    out << "<rect x=\"" << num(sx) << "\" y=\"" << num(row - 7) << "\" width=\"24\" height=\"14\" rx=\"7\" fill=\""
        << kSiteFill << "\" stroke=\"" << kSiteStroke << "\" stroke-width=\"1.3\"/>\n";
    text("sites: " + std::to_string(sites.size()));
    out << "<rect x=\"" << num(sx) << "\" y=\"" << num(row - 7) << "\" width=\"24\" height=\"14\" rx=\"7\" fill=\"none\" stroke=\""
        << kHiddenStroke << "\" stroke-width=\"1.1\" stroke-dasharray=\"4 3\"/>\n";
    text("hidden: " + std::to_string(hidden.size()));
    if (overlaps > 0) {
        out << "<rect x=\"" << num(sx) << "\" y=\"" << num(row - 7) << "\" width=\"24\" height=\"14\" fill=\"" << kSiteFill
            << "\"/>\n<rect x=\"" << num(sx) << "\" y=\"" << num(row - 7) << "\" width=\"24\" height=\"14\" fill=\""
            << kOverlapFill << "\" fill-opacity=\"" << kOverlapOpacity << "\"/>\n";
        text("overlapping pairs: " + std::to_string(overlaps));
    }
    out << "<line x1=\"" << num(sx) << "\" y1=\"" << num(row) << "\" x2=\"" << num(ex) << "\" y2=\"" << num(row)
        << "\" stroke=\"" << kDelaunay << "\" stroke-width=\"1\" stroke-dasharray=\"5 3\"/>\n";
    text("Delaunay edges: " + std::to_string(edges.size()));
    out << "<line x1=\"" << num(sx) << "\" y1=\"" << num(row) << "\" x2=\"" << num(ex) << "\" y2=\"" << num(row)
        << "\" stroke=\"" << kVoronoi << "\" stroke-width=\"2\"/>\n";
    text("Voronoi edges: " + std::to_string(d.arcs.size()));
    out << "<circle cx=\"" << num(0.5 * (sx + ex)) << "\" cy=\"" << num(row) << "\" r=\"3\" fill=\"" << kVertex << "\"/>\n";
    text("Voronoi vertices: " + std::to_string(faces.size()));
    out << "<text x=\"" << num(lx + 10) << "\" y=\"" << num(row + 4) << "\" font-size=\"11\" fill=\"#555\">arc tolerance "
        << num(d.tolerance) << " (" << num(100 * o.tolerance_fraction) << "% of box)</text>\n";
    row += 18;
    if (d.failed_edges > 0)
        out << "<text x=\"" << num(lx + 10) << "\" y=\"" << num(row + 4) << "\" font-size=\"11\" fill=\"#b00\">"
            << d.failed_edges << " edge(s) not drawn (uncertified vertex)</text>\n";
    out << "</g>\n";
    out << "</svg>\n";
}

TracedDiagram write_svg(std::ostream& out, const DelaunayGraph& graph, const std::vector<Ellipse>& sites,
                        const SvgOptions& options) {
    const TracedDiagram d = trace_voronoi_diagram(graph, sites, options.tolerance_fraction, options.margin_fraction);
    render_svg(out, graph, sites, d, options);
    return d;
}

}  // namespace ellvor
