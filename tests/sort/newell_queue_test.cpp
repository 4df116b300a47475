// Newell's candidate queue (sort/newell_queue.hpp) against a plain reference: random runs of taking the
// next candidate, putting polygons back at a new depth and taking waiting ones out, as Newell does with
// moves and cuts. The queue must always give the waiting polygon of largest zmax, the lower index on ties.
#include <hider/sort/newell_queue.hpp>

#include <random>
#include <set>
#include <utility>
#include <vector>

#include <doctest/doctest.h>

using namespace hider;

namespace {

struct Arrays {
    explicit Arrays(size_t cap) : store(cap), keys(cap), sort_scratch(cap), heap(cap), heap_pos(cap) {}
    std::vector<ScreenPoly> store;
    std::vector<SortKey> keys, sort_scratch;
    std::vector<uint32_t> heap, heap_pos;
    NewellScratch scratch() {
        NewellScratch s;
        s.keys = {keys.data(), keys.size()};
        s.sort_scratch = {sort_scratch.data(), sort_scratch.size()};
        s.heap = {heap.data(), heap.size()};
        s.heap_pos = {heap_pos.data(), heap_pos.size()};
        return s;
    }
};

/// The reference's order: the larger zmax first, then the lower index (as a set's first element).
using Waiting = std::set<std::pair<int64_t, uint32_t>>;  // (-zmax, id)

}  // namespace

TEST_CASE("Newell's queue gives the waiting polygon of largest zmax, lower index first, through moves and cuts") {
    long taken = 0, pushed = 0, dequeued = 0;
    for (uint32_t seed = 1; seed <= 40; ++seed) {
        std::mt19937 rng(seed);
        const size_t n = 1 + rng() % 300, cap = n + rng() % 200;
        const uint32_t depths = seed % 4 == 0 ? 8 : 1u << 20;  // few depths: ties everywhere
        Arrays a(cap);
        BoundedList<ScreenPoly> polys(a.store.data(), cap);
        Waiting waiting;
        for (uint32_t i = 0; i < n; ++i) {
            ScreenPoly p{};
            p.zmax = rng() % depths;
            polys.push_back(p);
            waiting.insert({-int64_t{p.zmax}, i});
        }
        const NewellScratch s = a.scratch();
        detail::NewellQueue q(polys, s);
        const Span<const SortKey> sorted = q.start();
        REQUIRE(sorted.size() == n);
        {
            auto it = waiting.begin();
            for (size_t i = 0; i < n; ++i, ++it) CHECK(sorted[i].index == it->second);  // the input, farthest first
        }
        std::vector<uint32_t> out;  // polygons taken and not waiting again
        for (int step = 0; step < 3000 && !(waiting.empty() && out.empty()); ++step) {
            const uint32_t op = rng() % 8;
            if (op < 4 || (out.empty() && waiting.size() < 2)) {
                const uint32_t id = q.next();
                if (waiting.empty()) {
                    CHECK(id == detail::NewellQueue::kNone);
                } else {
                    INFO("seed ", seed, " step ", step);
                    REQUIRE(id == waiting.begin()->second);
                    waiting.erase(waiting.begin());
                    out.push_back(id);
                    ++taken;
                }
            } else if (op < 6 && !out.empty()) {
                // Moved back, or the far piece of a cut: it waits again, perhaps at another depth.
                const size_t k = rng() % out.size();
                const uint32_t id = out[k];
                out.erase(out.begin() + static_cast<ptrdiff_t>(k));
                if (rng() % 2 == 0) polys[id].zmax = rng() % depths;
                q.push(id);
                waiting.insert({-int64_t{polys[id].zmax}, id});
                ++pushed;
            } else if (op == 6 && polys.size() < cap) {
                // The near piece of a cut: a new polygon.
                ScreenPoly p{};
                p.zmax = rng() % depths;
                polys.push_back(p);
                const uint32_t id = static_cast<uint32_t>(polys.size() - 1);
                q.push(id);
                waiting.insert({-int64_t{p.zmax}, id});
                ++pushed;
            } else if (!waiting.empty()) {
                // A waiting polygon taken out (about to be cut or to become the candidate), maybe put back.
                auto it = waiting.begin();
                std::advance(it, static_cast<ptrdiff_t>(rng() % waiting.size()));
                const uint32_t id = it->second;
                waiting.erase(it);
                q.dequeue(id);
                out.push_back(id);
                ++dequeued;
            }
        }
        while (!waiting.empty()) {  // the rest leave in order
            REQUIRE(q.next() == waiting.begin()->second);
            waiting.erase(waiting.begin());
        }
        CHECK(q.next() == detail::NewellQueue::kNone);
    }
    MESSAGE(taken << " taken, " << pushed << " put back or added, " << dequeued << " taken out while waiting");
    CHECK(taken > 20000);
    CHECK(pushed > 5000);
    CHECK(dequeued > 5000);
}
