#include "tests/support/signed_distance_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace ellvor::test {

// ---- The signed distance ------------------------------------------------------------------------------------

namespace {

// Sign of a coordinate for reflecting back out of the first quadrant (0 counts
// as positive: either mirror image is a nearest point then).
Real with_sign_of(const Real& magnitude, const Real& coordinate) {
    return coordinate.sign() < 0 ? -magnitude : magnitude;
}

// The nearest point of the ellipse ξ²/A² + η²/B² = 1 (A > B) to (p, q) with p,
// q >= 0, which lies in the same quadrant (reflecting a point across an axis
// only moves it away). Closed forms on the long axis; elsewhere the foot is
// ((A² p/(u + D), B² q/u)) for the one root u > 0 of
//     F(u) = (A p / (u + D))² + (B q / u)² - 1,   D = A² - B²,
// the condition "the point lies on the normal at the foot": F falls from +∞ to
// -1 on (0, ∞) and is convex (Eberly, "Distance from a point to an ellipse").
// u = t + B² for Eberly's t, so that near the pole (points near the medial
// axis, thin ellipses) u keeps its relative precision.
RealPoint nearest_in_first_quadrant(const Real& A, const Real& B, const Real& p, const Real& q) {
    const Real D = A * A - B * B;
    if (q.sign() == 0) {
        // On the long axis: between the centres of curvature of the vertices
        // (inside, on the medial axis) two mirror feet, else the vertex.
        if (p < D / A) {
            const Real xi = A * A * p / D;
            return {xi, B * sqrt(Real(1) - (xi / A) * (xi / A))};
        }
        return {A, Real(0)};
    }
    const Real Ap = A * p, Bq = B * q;
    auto F = [&](const Real& u) {
        const Real s = Ap / (u + D), r = Bq / u;
        return s * s + r * r - Real(1);
    };
    auto dF = [&](const Real& u) {
        const Real s = Ap / (u + D), r = Bq / u;
        return -Real(2) * (s * s / (u + D) + r * r / u);
    };
    // F(lo) >= 0 (one term alone reaches 1 there) and F(hi) <= 0.
    Real lo = Bq, hi = hypot(Ap, Bq);
    if (Ap - D > lo) lo = Ap - D;
    Real F_lo = F(lo), F_hi = F(hi);
    // Newton from the left never overshoots a convex decreasing function, and
    // the secant of a bracket lands right of the root: both ends close in, the
    // left one quadratically. A bisection keeps the worst case linear.
    const Real relative_tolerance = std::ldexp(1.0, -static_cast<int>(kOracleBits) + 8);
    for (int iteration = 0;; ++iteration) {
        if (iteration == 4 * kOracleBits + 1000) throw std::runtime_error("oracle: no convergence of the foot point");
        if (F_lo.sign() == 0 || hi - lo <= lo * relative_tolerance) break;
        const Real width = hi - lo;
        auto tighten = [&](const Real& u) {
            if (!(u > lo && u < hi)) return;
            Real F_u = F(u);
            if (F_u.sign() >= 0) lo = u, F_lo = std::move(F_u);
            else hi = u, F_hi = std::move(F_u);
        };
        tighten(lo - F_lo / dF(lo));
        if (F_lo > F_hi) tighten(lo - F_lo * (hi - lo) / (F_hi - F_lo));
        if (hi - lo > width / Real(2)) tighten((lo + hi) / Real(2));
        if (hi - lo == width) break;  // nothing moved: the rounding level
    }
    return {A * Ap / (lo + D), B * Bq / lo};
}

RealPoint unit(const Real& x, const Real& y) {
    const Real n = hypot(x, y);
    return {x / n, y / n};
}

}  // namespace

OracleEllipse::OracleEllipse(const Ellipse& e)
    : center_{Real(e.xc()), Real(e.yc())}, circle_(e.is_circle()) {
    const Real c(e.cos_rotation()), s(e.sin_rotation());
    if (e.b() <= e.a()) {
        A_ = Real(e.a()), B_ = Real(e.b());
        U_ = {c, s}, V_ = {-s, c};
    } else {
        A_ = Real(e.b()), B_ = Real(e.a());
        U_ = {-s, c}, V_ = {c, s};
    }
}

RealPoint OracleEllipse::to_world(const Real& xi, const Real& eta) const {
    return {center_.x + xi * U_.x + eta * V_.x, center_.y + xi * U_.y + eta * V_.y};
}

SignedDistance OracleEllipse::signed_distance(const RealPoint& x) const {
    const Real dx = x.x - center_.x, dy = x.y - center_.y;
    const Real xi = dx * U_.x + dy * U_.y, eta = dx * V_.x + dy * V_.y;
    SignedDistance out;
    if (circle_) {
        const Real r = hypot(xi, eta);
        const RealPoint direction = r.sign() == 0 ? RealPoint{Real(1), Real(0)} : RealPoint{xi / r, eta / r};
        out.value = r - A_;
        out.foot = to_world(A_ * direction.x, A_ * direction.y);
        out.medial = center_;
        out.normal = {direction.x * U_.x + direction.y * V_.x, direction.x * U_.y + direction.y * V_.y};
        return out;
    }
    const Real p = abs(xi), q = abs(eta);
    const RealPoint f = nearest_in_first_quadrant(A_, B_, p, q);
    // The sign from the implicit equation, the magnitude from the foot.
    const Real implicit = (p / A_) * (p / A_) + (q / B_) * (q / B_) - Real(1);
    const Real magnitude = hypot(p - f.x, q - f.y);
    out.value = implicit.sign() < 0 ? -magnitude : magnitude;
    const Real foot_xi = with_sign_of(f.x, xi), foot_eta = with_sign_of(f.y, eta);
    out.foot = to_world(foot_xi, foot_eta);
    // The normal at (ξ, η) meets the long axis at ((A² - B²) ξ / A², 0).
    out.medial = to_world((A_ * A_ - B_ * B_) * foot_xi / (A_ * A_), Real(0));
    const RealPoint n = unit(foot_xi / (A_ * A_), foot_eta / (B_ * B_));
    out.normal = {n.x * U_.x + n.y * V_.x, n.x * U_.y + n.y * V_.y};
    return out;
}

Real OracleEllipse::distance_lower_bound(const RealPoint& x) const {
    return hypot(x.x - center_.x, x.y - center_.y) - A_;
}

RealPoint OracleEllipse::medial_axis_point(const Real& s) const {
    return to_world(s * (A_ * A_ - B_ * B_) / A_, Real(0));
}

RealPoint OracleEllipse::boundary_point(const Real& theta) const {
    return to_world(A_ * cos(theta), B_ * sin(theta));
}

RealPoint OracleEllipse::medial_point_below(const Real& theta) const {
    return medial_axis_point(cos(theta));
}

// ---- The diagram checks -------------------------------------------------------------------------------------

namespace {

// |δ(V, E) - ρ| <= |V - V*| + |ρ - ρ*| <= (√2 + 1) error for the exact vertex
// (V*, ρ*): δ is 1-Lipschitz.
constexpr double kVertexErrorFactor = 2.5;
// The differences are taken at kOracleBits, so the slack only covers `error`
// being a rounded double itself: 1e-12 of the scene is far above that and far
// below any real defect.
constexpr double kVertexSlack = 1e-12;
// How much nearer a site must be to own a point.
constexpr double kOwnershipMargin = 1e-9;
constexpr int kHiddenMedialSamples = 200;
constexpr int kHiddenBoundarySamples = 64;
constexpr int kWitnessMedialSamples = 33;
// Normals of a face's three feet closer than this (radians) leave its
// orientation undecided here.
constexpr double kAngleSlack = 1e-6;
constexpr std::size_t kMaxReported = 20;

std::string point_str(const RealPoint& x) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << x.x.to_double() << ", " << x.y.to_double() << ")";
    return s.str();
}

std::string num(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

// Evenly spread parameters in [-1, 1], ends included (0 alone for one sample).
std::vector<Real> spread(int count) {
    if (count == 1) return {Real(0)};
    std::vector<Real> s;
    for (int i = 0; i < count; ++i) s.push_back(Real(-1) + Real(2 * i) / Real(count - 1));
    return s;
}

class DiagramChecker {
public:
    DiagramChecker(const std::vector<Ellipse>& sites, const DiagramClaim& claim) : sites_(sites), claim_(claim) {}

    std::string run() {
        if (!check_structure()) return report();
        double extent = 0;
        for (SiteId id : inserted_) {
            const Ellipse& e = sites_[id];
            oracle_.emplace(id, OracleEllipse(e));
            const double radius = std::max(e.a().to_double(), e.b().to_double());
            extent = std::max({extent, std::fabs(e.xc().to_double()) + radius, std::fabs(e.yc().to_double()) + radius});
        }
        scale_ = extent;  // > 0 unless nothing is inserted
        margin_ = kOwnershipMargin * scale_;
        find_twins();
        check_faces();
        check_visible_sites_own_points();
        check_hidden_sites_own_nothing();
        return report();
    }

private:
    void problem(const std::string& line) {
        ++problem_count_;
        if (problems_.size() < kMaxReported) problems_.push_back(line);
    }

    std::string report() const {
        std::string out;
        for (const std::string& p : problems_) out += p + "\n";
        if (problem_count_ > problems_.size())
            out += "... and " + std::to_string(problem_count_ - problems_.size()) + " more problems\n";
        return out;
    }

    // Ids in range, each site once, hosts and face sites visible, one vertex a
    // face. False when the rest cannot run (an id out of range, a face site not
    // in the graph, vertices missing).
    bool check_structure() {
        enum class Role { visible, hidden };
        auto role_name = [](Role r) { return r == Role::visible ? "visible" : "hidden"; };
        std::map<SiteId, Role> role;
        bool usable = true;
        auto claim_site = [&](SiteId id, Role as) {
            if (id >= sites_.size()) {
                problem("site " + std::to_string(id) + " (" + role_name(as) + ") is out of range: " +
                        std::to_string(sites_.size()) + " sites");
                usable = false;
                return;
            }
            const auto [it, fresh] = role.emplace(id, as);
            if (!fresh)
                problem("site " + std::to_string(id) + " is listed as " + role_name(it->second) + " and as " +
                        role_name(as));
            else inserted_.push_back(id);
        };
        for (SiteId v : claim_.visible) claim_site(v, Role::visible);
        for (const auto& [h, host] : claim_.hidden) claim_site(h, Role::hidden);
        std::sort(inserted_.begin(), inserted_.end());
        auto is_visible = [&](SiteId id) {
            const auto it = role.find(id);
            return it != role.end() && it->second == Role::visible;
        };
        for (const auto& [h, host] : claim_.hidden)
            if (!is_visible(host))
                problem("hidden site " + std::to_string(h) + " is hidden by site " + std::to_string(host) +
                        ", which is not visible");
        for (const auto& f : claim_.faces) {
            for (SiteId s : f)
                if (!is_visible(s)) {
                    problem("face " + face_str(f) + " has site " + std::to_string(s) + ", which is not visible");
                    usable = usable && role.count(s);  // the checks below need its distance
                }
            if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) problem("face " + face_str(f) + " repeats a site");
        }
        if (claim_.vertices.size() != claim_.faces.size()) {
            problem(std::to_string(claim_.faces.size()) + " faces but " + std::to_string(claim_.vertices.size()) +
                    " Voronoi vertices");
            usable = false;
        }
        return usable;
    }

    static std::string face_str(const std::array<SiteId, 3>& f) {
        return "(" + std::to_string(f[0]) + ", " + std::to_string(f[1]) + ", " + std::to_string(f[2]) + ")";
    }

    // Some other inserted site E' with δ(x, E') <= δ(x, owner) + margin (the
    // hint first, then the last one found: usually the same site wins
    // repeatedly), or none: owner then owns x strictly.
    // With skip_twins, the owner's twins (find_twins) do not challenge.
    std::optional<std::pair<SiteId, Real>> challenger(const RealPoint& x, SiteId owner, const Real& owner_distance,
                                                      std::optional<SiteId> hint = std::nullopt, bool skip_twins = false) {
        const Real reach = owner_distance + Real(margin_);
        auto challenges = [&](SiteId id) -> std::optional<std::pair<SiteId, Real>> {
            if (id == owner) return std::nullopt;
            if (skip_twins && twins_.count({std::min(id, owner), std::max(id, owner)})) return std::nullopt;
            const OracleEllipse& e = oracle_.at(id);
            if (e.distance_lower_bound(x) > reach) return std::nullopt;
            Real d = e.signed_distance_value(x);
            if (d > reach) return std::nullopt;
            last_challenger_ = id;
            return std::make_pair(id, std::move(d));
        };
        for (std::optional<SiteId> first : {hint, last_challenger_})
            if (first && oracle_.count(*first))
                if (auto c = challenges(*first)) return c;
        for (SiteId id : inserted_)
            if (auto c = challenges(id)) return c;
        return std::nullopt;
    }

    // Twins: two inserted sites whose boundaries are within the margin of each
    // other (a Hausdorff bound from the parameters: centers, semi-axes, and the
    // larger semi-axis times the angle, |d omega| <= 2 |d w|), so that
    // |delta(x, E) - delta(x, E')| < margin everywhere: a nearly coincident
    // pair (tests/graph/test_near_duplicate_sites.cpp). No point is nearer to
    // one of them by the margin, so a visible site is checked to own a point
    // against the sites other than its twins; how the pair's cells split is
    // left to the faces' check.
    void find_twins() {
        for (std::size_t i = 0; i < inserted_.size(); ++i)
            for (std::size_t j = i + 1; j < inserted_.size(); ++j) {
                const Ellipse &p = sites_[inserted_[i]], &q = sites_[inserted_[j]];
                auto gap = [](const Rational& x, const Rational& y) { return std::fabs((x - y).to_double()); };
                const double bound = std::hypot(gap(p.xc(), q.xc()), gap(p.yc(), q.yc())) +
                                     std::max(gap(p.a(), q.a()), gap(p.b(), q.b())) +
                                     2 * gap(p.w(), q.w()) * std::max(p.a().to_double(), p.b().to_double());
                if (bound < 0.5 * margin_) twins_.insert({inserted_[i], inserted_[j]});
            }
    }

    // The other inserted site nearest to x, for messages.
    std::pair<SiteId, Real> nearest_other(const RealPoint& x, SiteId owner) const {
        std::optional<std::pair<SiteId, Real>> best;
        for (SiteId id : inserted_) {
            if (id == owner) continue;
            Real d = oracle_.at(id).signed_distance_value(x);
            if (!best || d < best->second) best = std::make_pair(id, std::move(d));
        }
        return best ? *best : std::make_pair(owner, Real(0));
    }

    void check_faces() {
        for (std::size_t k = 0; k < claim_.faces.size(); ++k) {
            const auto& f = claim_.faces[k];
            const VoronoiVertexValue& v = claim_.vertices[k];
            const RealPoint V{Real(v.x), Real(v.y)};
            const Real rho(v.radius);
            const double tol = kVertexErrorFactor * v.error + kVertexSlack * scale_;
            const std::string where = "face " + face_str(f) + " with vertex V = " + point_str(V) + ", rho = " +
                                      num(v.radius) + " (tol " + num(tol) + "): ";
            std::array<double, 3> normal_angle{};
            for (int i = 0; i < 3; ++i) {
                const SignedDistance d = oracle_.at(f[i]).signed_distance(V);
                const double off = (d.value - rho).to_double();
                if (std::fabs(off) > tol)
                    problem(where + "delta(V, site " + std::to_string(f[i]) + ") = " + num(d.value.to_double()) +
                            " is off rho by " + num(off));
                normal_angle[i] = std::atan2(d.normal.y.to_double(), d.normal.x.to_double());
            }
            check_orientation(normal_angle, where);
            const Real lowest = rho - Real(tol);
            for (SiteId id : inserted_) {
                if (id == f[0] || id == f[1] || id == f[2]) continue;
                const OracleEllipse& e = oracle_.at(id);
                if (e.distance_lower_bound(V) >= lowest) continue;
                const Real d = e.signed_distance_value(V);
                if (d < lowest)
                    problem(where + "site " + std::to_string(id) + " is nearer: delta(V, site " + std::to_string(id) +
                            ") = " + num(d.to_double()) + " < rho by " + num((rho - d).to_double()));
            }
        }
    }

    // The feet's normals counter-clockwise in the face's order (docs/DESIGN.md
    // §2: the tangency points' orientation is the normals' for every ρ).
    void check_orientation(const std::array<double, 3>& angle, const std::string& where) {
        const double two_pi = 2 * std::acos(-1.0);
        auto turn = [&](double from, double to) { return std::fmod(std::fmod(to - from, two_pi) + two_pi, two_pi); };
        const double to_second = turn(angle[0], angle[1]), to_third = turn(angle[0], angle[2]);
        // Clockwise: third, then second, then back to first, each step clear.
        if (to_third > kAngleSlack && to_second - to_third > kAngleSlack && two_pi - to_second > kAngleSlack)
            problem(where + "the feet are clockwise (normal angles " + num(angle[0]) + ", " + num(angle[1]) + ", " +
                    num(angle[2]) + ")");
    }

    void check_visible_sites_own_points() {
        std::map<SiteId, std::vector<std::size_t>> faces_of;
        for (std::size_t k = 0; k < claim_.faces.size(); ++k)
            for (SiteId s : claim_.faces[k]) faces_of[s].push_back(k);
        for (SiteId e : claim_.visible) {
            const OracleEllipse& site = oracle_.at(e);
            // Along the normal from a Voronoi vertex V through E's foot to E's
            // medial axis the points stay in E's closed cell, and δ(·, E) falls
            // at rate 1 while every other δ falls at rate <= 1: the medial end
            // is the best witness on that normal.
            std::vector<RealPoint> candidates;
            for (std::size_t k : faces_of[e]) {
                const VoronoiVertexValue& v = claim_.vertices[k];
                candidates.push_back(site.signed_distance({Real(v.x), Real(v.y)}).medial);
            }
            for (const Real& s : spread(sites_[e].is_circle() ? 1 : kWitnessMedialSamples))
                candidates.push_back(site.medial_axis_point(s));
            std::optional<std::string> last_failure;
            bool owns = false;
            for (const RealPoint& x : candidates) {
                const Real d = site.signed_distance_value(x);
                const auto rival = challenger(x, e, d, std::nullopt, true);
                if (!rival) {
                    owns = true;
                    break;
                }
                last_failure = "at " + point_str(x) + " delta(site " + std::to_string(e) + ") = " + num(d.to_double()) +
                               ", delta(site " + std::to_string(rival->first) + ") = " +
                               num(rival->second.to_double());
            }
            if (!owns)
                problem("visible site " + std::to_string(e) + " owns no point: none of " +
                        std::to_string(candidates.size()) + " candidates is nearer to it than to every other site by " +
                        num(margin_) + "; last " + *last_failure);
        }
    }

    void check_hidden_sites_own_nothing() {
        for (const auto& [h, host] : claim_.hidden) {
            const OracleEllipse& site = oracle_.at(h);
            std::vector<RealPoint> samples;
            for (const Real& s : spread(sites_[h].is_circle() ? 1 : kHiddenMedialSamples))
                samples.push_back(site.medial_axis_point(s));
            for (int i = 0; i < kHiddenBoundarySamples; ++i) {
                const Real theta = Real(2 * i) * Real::pi() / Real(kHiddenBoundarySamples);
                const RealPoint b = site.boundary_point(theta), m = site.medial_point_below(theta);
                samples.push_back(b);
                samples.push_back({(b.x + m.x) / Real(2), (b.y + m.y) / Real(2)});
            }
            for (const RealPoint& x : samples) {
                const Real d = site.signed_distance_value(x);
                if (challenger(x, h, d, host)) continue;
                const auto [other, other_distance] = nearest_other(x, h);
                problem("hidden site " + std::to_string(h) + " (hidden by " + std::to_string(host) + ") owns " +
                        point_str(x) + ": delta(site " + std::to_string(h) + ") = " + num(d.to_double()) +
                        ", nearest other site " + std::to_string(other) + " at " + num(other_distance.to_double()) +
                        " (margin " + num(margin_) + ")");
                break;
            }
        }
    }

    const std::vector<Ellipse>& sites_;
    const DiagramClaim& claim_;
    std::vector<SiteId> inserted_;  // visible and hidden, increasing
    std::map<SiteId, OracleEllipse> oracle_;
    double scale_ = 0;   // the largest |coordinate| the inserted sites reach
    double margin_ = 0;  // how much nearer an owner must be
    std::optional<SiteId> last_challenger_;
    std::set<std::pair<SiteId, SiteId>> twins_;  // (smaller id, larger id)
    std::vector<std::string> problems_;
    std::size_t problem_count_ = 0;
};

}  // namespace

DiagramClaim claim_of(const DelaunayGraph& graph, const std::vector<Ellipse>& sites) {
    DiagramClaim claim{graph.visible_sites(), graph.hidden(), graph.faces(), {}};
    for (const auto& f : claim.faces) claim.vertices.push_back(voronoi_vertex_value(sites, f));
    return claim;
}

std::string check_diagram(const std::vector<Ellipse>& sites, const DiagramClaim& claim) {
    return DiagramChecker(sites, claim).run();
}

std::string check_diagram(const std::vector<Ellipse>& sites, const DelaunayGraph& graph) {
    const DiagramClaim claim = claim_of(graph, sites);
    std::string problems;
    std::vector<char> listed(sites.size(), 0);
    for (SiteId v : claim.visible) listed.at(v) = 1;
    for (const auto& [h, host] : claim.hidden) listed.at(h) = 1;
    for (SiteId id = 0; id < sites.size(); ++id)
        if (graph.contains(id) && !listed[id])
            problems += "site " + std::to_string(id) + " is in the graph but neither visible nor hidden\n";
    return problems + check_diagram(sites, claim);
}

}  // namespace ellvor::test
