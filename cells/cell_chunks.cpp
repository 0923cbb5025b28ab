#include "cells/cell_chunks.hpp"

#include "graph/insertion_order.hpp"
#include "subdivision/ellipse_shape.hpp"
#include "util/error.hpp"

#include <flint/flint.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <thread>

namespace ellvor {

std::vector<SiteId> hilbert_order(const std::vector<Ellipse>& sites, std::vector<SiteId> which) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    std::vector<std::uint32_t> place(sites.size(), 0);
    for (SiteId s : which) {
        const EllipseShape e = EllipseShape::of(sites.at(s));
        lo[0] = std::min(lo[0], e.xc), lo[1] = std::min(lo[1], e.yc);
        hi[0] = std::max(hi[0], e.xc), hi[1] = std::max(hi[1], e.yc);
    }
    const double side = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    for (SiteId s : which) {
        const EllipseShape e = EllipseShape::of(sites[s]);
        place[s] = hilbert_index(e.xc, e.yc, lo[0], lo[1], side);
    }
    std::stable_sort(which.begin(), which.end(), [&](SiteId a, SiteId b) { return place[a] < place[b]; });
    return which;
}

void for_each_chunk(const std::vector<SiteId>& order, std::size_t chunk, unsigned threads,
                    const std::function<void(const SiteId* begin, const SiteId* end)>& work) {
    if (chunk == 0) throw Error("for_each_chunk: chunks of no cells");
    const std::size_t chunks = (order.size() + chunk - 1) / chunk;
    std::atomic<std::size_t> next_chunk{0}, first_failed{chunks};
    std::vector<std::exception_ptr> errors(chunks);
    const auto run = [&] {
        for (std::size_t c; (c = next_chunk.fetch_add(1)) < chunks;) {
            // After a failed chunk only the chunks before it.
            if (c > first_failed.load()) continue;
            try {
                const SiteId* begin = order.data() + c * chunk;
                work(begin, order.data() + std::min(order.size(), (c + 1) * chunk));
            } catch (...) {
                errors[c] = std::current_exception();
                for (std::size_t f = first_failed.load(); c < f && !first_failed.compare_exchange_weak(f, c);) {
                }
            }
        }
    };
    if (threads == 0) threads = std::max(1U, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, chunks)));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back([&run] {
            run();
            flint_cleanup();  // the thread's own caches (Arb's constants, FLINT's integers)
        });
    run();
    for (std::thread& t : pool) t.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

}  // namespace ellvor
