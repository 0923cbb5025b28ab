// EllipseDelaunayTraits with every predicate call timed, for the benchmarks
// that look for slow calls (near_degenerate, near_duplicates).
#pragma once

#include "decision/delaunay_traits.hpp"
#include "traits/ellipse_delaunay_traits.hpp"

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace ellvor::experiments {

// How long the predicates of one build took: the graph's calls through its
// traits, timed one by one (steady_clock; memoized answers count as calls).

struct CallProfile {
    std::uint64_t calls = 0;
    double seconds = 0, slowest = 0;
    std::array<std::uint64_t, kPredicates.size()> calls_of{};  // indexed by Predicate
    std::array<double, kPredicates.size()> seconds_of{};
    std::string slowest_call;  // "incircle(4, 9, 17, 2)"
    // Makes the slowest call again on other traits.
    std::function<void(DelaunayTraits&)> replay_slowest;
};

// EllipseDelaunayTraits with every predicate call timed.
class TimedTraits final : public DelaunayTraits {
public:
    explicit TimedTraits(std::vector<Ellipse> sites) : inner_(std::move(sites)) {}
    const CallProfile& profile() const { return profile_; }

    std::size_t size() const override { return inner_.size(); }
    Sign compare_weight(SiteId a, SiteId b) const override { return inner_.compare_weight(a, b); }
    std::optional<WeightBounds> weight_bounds(SiteId i) const override { return inner_.weight_bounds(i); }
    LocationHint location_hint(SiteId i) const override { return inner_.location_hint(i); }
    void check_sites() override { inner_.check_sites(); }
    bool is_hidden(SiteId p, SiteId q) override {
        return timed(Predicate::is_hidden, {p, q}, [=](DelaunayTraits& t) { return t.is_hidden(p, q); });
    }
    bool crosses(SiteId p, SiteId q) override {
        return timed(Predicate::is_hidden, {p, q}, [=](DelaunayTraits& t) { return t.crosses(p, q); });
    }
    Sign side_of_bisector(SiteId i, SiteId j, SiteId k) override {
        return timed(Predicate::side_of_bisector, {i, j, k}, [=](DelaunayTraits& t) { return t.side_of_bisector(i, j, k); });
    }
    Sign infinite_vertex_conflict(SiteId i, SiteId j, SiteId q) override {
        return timed(Predicate::infinite_vertex_conflict, {i, j, q}, [=](DelaunayTraits& t) { return t.infinite_vertex_conflict(i, j, q); });
    }
    Sign incircle(SiteId i, SiteId j, SiteId k, SiteId q) override {
        return timed(Predicate::incircle, {i, j, k, q}, [=](DelaunayTraits& t) { return t.incircle(i, j, k, q); });
    }
    bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) override {
        return timed(Predicate::finite_edge_interior_conflict, {p1, p2, p3, p4, q},
                     [=](DelaunayTraits& t) { return t.finite_edge_interior_conflict(p1, p2, p3, p4, q, b); });
    }
    bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId p3, SiteId q, bool b) override {
        return timed(Predicate::finite_edge_interior_conflict, {p1, p2, p3, q}, [=](DelaunayTraits& t) { return t.finite_edge_interior_conflict(p1, p2, p3, q, b); });
    }
    bool finite_edge_interior_conflict(SiteId p1, SiteId p2, SiteId q, bool b) override {
        return timed(Predicate::finite_edge_interior_conflict, {p1, p2, q}, [=](DelaunayTraits& t) { return t.finite_edge_interior_conflict(p1, p2, q, b); });
    }
    bool infinite_edge_interior_conflict(SiteId p2, SiteId p3, SiteId p4, SiteId q, bool b) override {
        return timed(Predicate::infinite_edge_interior_conflict, {p2, p3, p4, q},
                     [=](DelaunayTraits& t) { return t.infinite_edge_interior_conflict(p2, p3, p4, q, b); });
    }
    bool is_degenerate_edge(SiteId p1, SiteId p2, SiteId p3, SiteId p4) override {
        return timed(Predicate::is_degenerate_edge, {p1, p2, p3, p4},
                     [=](DelaunayTraits& t) { return t.is_degenerate_edge(p1, p2, p3, p4); });
    }
    void forget_face(SiteId i, SiteId j, SiteId k) override { inner_.forget_face(i, j, k); }
    const TraitsStats& stats() const override { return inner_.stats(); }

private:
    // Calls `call` on the inner traits, timed; keeps it (by value) when it is the slowest so far.
    template <class F>
    auto timed(Predicate which, std::initializer_list<SiteId> ids, F call) -> decltype(call(std::declval<DelaunayTraits&>())) {
        const auto t0 = std::chrono::steady_clock::now();
        auto answer = call(inner_);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ++profile_.calls;
        profile_.seconds += s;
        ++profile_.calls_of[static_cast<std::size_t>(which)];
        profile_.seconds_of[static_cast<std::size_t>(which)] += s;
        if (s > profile_.slowest) {
            profile_.slowest = s;
            profile_.slowest_call = std::string(predicate_name(which)) + "(";
            for (const SiteId* i = ids.begin(); i != ids.end(); ++i)
                profile_.slowest_call += (i == ids.begin() ? "" : ", ") + std::to_string(*i);
            profile_.slowest_call += ")";
            profile_.replay_slowest = [call](DelaunayTraits& t) { call(t); };
        }
        return answer;
    }

    EllipseDelaunayTraits inner_;
    CallProfile profile_;
};

}  // namespace ellvor::experiments
