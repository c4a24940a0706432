// Peer: Bullet's btDbvtBroadphase (Debian's libbullet-dev, single precision) on W1, the same boxes
// and queries as aabb_bench.cpp.
//
// Notes from Bullet 3.24's btDbvtBroadphase.cpp (not installed; read upstream) and from runs:
// - createProxy inserts the box into the dynamic tree. With m_deferedcollide = false it also
//   collides the new box against both trees at once, so the pair cache is complete after the
//   last createProxy. With m_deferedcollide = true it does not, and the first
//   calculateOverlappingPairs collides the dynamic tree with itself (and with the fixed tree,
//   empty here): ONE call reports every pair. The second call moves every proxy to the fixed
//   tree (a remove and reinsert each, as costly as the first call or more) and adds no pair.
// - The dispatcher is only used to free the collision algorithms of pairs the cleanup removes;
//   none is removed here and no pair has an algorithm, so nullptr is safe (Bullet's own
//   btDbvtBroadphase::benchmark passes 0 too).
// - Overlap is closed (btDbvt's Intersect rejects only max < min), like W1, so the counts match
//   the reference exactly.
// - aabbTest ignores the filter group and mask; the pair cache checks them, hence AllFilter.
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "bench/bench_common.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wshadow"
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <LinearMath/btAlignedAllocator.h>
#pragma GCC diagnostic pop

namespace simdphys::bench {
namespace {

constexpr std::size_t kSizes[] = {100'000, 1'000'000};

btVector3 toBullet(const Vec3f& v) { return btVector3(v.x(), v.y(), v.z()); }

// A broadphase holding one proxy per box; a proxy's user pointer is its box index.
class Dbvt {
 public:
  Dbvt(const BoxStream& boxes, bool deferred) : bp_(std::make_unique<btDbvtBroadphase>()) {
    bp_->m_deferedcollide = deferred;
    proxies_.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const Aabb b = boxes[i];
      proxies_.push_back(bp_->createProxy(toBullet(b.min), toBullet(b.max), 0,
                                          reinterpret_cast<void*>(i), btBroadphaseProxy::AllFilter,
                                          btBroadphaseProxy::AllFilter, nullptr));
    }
  }
  Dbvt(const Dbvt&) = delete;
  Dbvt& operator=(const Dbvt&) = delete;
  // ~btDbvtBroadphase frees the trees and the pair cache, not the proxies. destroyProxy would,
  // but each call scans the whole hashed pair cache (removeOverlappingPairsContainingProxy):
  // O(N x pairs), hours at N = 1,000,000. A proxy is plain data from btAlignedAlloc, so it is
  // freed directly once the broadphase pointing to it is gone.
  ~Dbvt() {
    bp_.reset();
    for (btBroadphaseProxy* p : proxies_) btAlignedFree(p);
  }
  btDbvtBroadphase& operator*() { return *bp_; }
  btDbvtBroadphase* operator->() { return bp_.get(); }

 private:
  std::unique_ptr<btDbvtBroadphase> bp_;
  std::vector<btBroadphaseProxy*> proxies_;
};

struct CountCallback : btBroadphaseAabbCallback {
  std::uint64_t count = 0;
  bool process(const btBroadphaseProxy*) override {
    ++count;
    return true;
  }
};

// aabb_query: the tree as createProxy builds it (deferred, so no pairs are computed), outside
// the timed loop. Neither optimize() (a top-down rebuild) nor settling the proxies into the fixed
// tree (two calculateOverlappingPairs) made the queries faster, so the tree is left as inserted.
void registerQuery(std::size_t n) {
  registerOnce("aabb_query", "bullet_dbvt", "peer", n, [n](benchmark::State& state) {
    const auto& w = aabbWorkload(n);
    Dbvt dbvt(w.boxes, true);
    std::vector<std::pair<btVector3, btVector3>> queries;
    for (const Aabb& q : w.queries) queries.emplace_back(toBullet(q.min), toBullet(q.max));
    std::uint64_t count = 0;
    for (auto _ : state) {
      CountCallback callback;
      for (const auto& [min, max] : queries) dbvt->aabbTest(min, max, callback);
      benchmark::DoNotOptimize(count = callback.count);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * queries.size() * n));
    checkExact(state, count, aabbReference(n).queryOverlaps);
  });
}

// aabb_pairs: timed per iteration, a fresh broadphase, N createProxy, the calls to
// calculateOverlappingPairs the mode needs for the complete set (deferred 1, immediate 0; see the
// top), the pair cache read, and the teardown. Only the conversion of the pairs to box indices for
// the checksum is left out of the timing. Deferred is the one to compare against: the faster at
// both sizes (medians of 5 runs on a shared 2-core machine: 148 ms against 220 ms at N =
// 100,000, 6.1 s against 12.9 s of CPU at 1,000,000) and Bullet's own choice for large scenes.
// Immediate mode's createProxy collides each new box with the growing tree, one tree query per box;
// deferred collides the finished tree with itself once. At 1,000,000 deferred spends about 3.2 s in
// createProxy, 2.0 s in the one calculateOverlappingPairs and 0.2 s in the teardown.
void registerPairs(std::size_t n, const char* method, bool deferred) {
  registerOnce("aabb_pairs", method, "peer", n, [n, deferred](benchmark::State& state) {
    const auto& w = aabbWorkload(n);
    const auto& ref = aabbReference(n);
    const int calls = deferred ? 1 : 0;
    std::vector<Pair> pairs;
    for (auto _ : state) {
      Dbvt dbvt(w.boxes, deferred);
      for (int c = 0; c < calls; ++c) dbvt->calculateOverlappingPairs(nullptr);
      const btBroadphasePairArray& found =
          dbvt->getOverlappingPairCache()->getOverlappingPairArray();
      benchmark::DoNotOptimize(found.size());
      state.PauseTiming();
      pairs.clear();
      pairs.reserve(std::size_t(found.size()));
      for (int i = 0; i < found.size(); ++i) {
        const auto a =
            std::uint32_t(reinterpret_cast<std::uintptr_t>(found[i].m_pProxy0->m_clientObject));
        const auto b =
            std::uint32_t(reinterpret_cast<std::uintptr_t>(found[i].m_pProxy1->m_clientObject));
        pairs.push_back(a < b ? Pair{a, b} : Pair{b, a});
      }
      state.ResumeTiming();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
    state.counters["calls"] = calls;
    state.counters["checksum_ok"] = scenes::pairChecksum(pairs, n) == ref.checksum ? 1 : 0;
    checkExact(state, pairs.size(), ref.pairs);
  });
}

}  // namespace

void registerBulletBenchmarks() {
  for (std::size_t n : kSizes) registerQuery(n);
  for (std::size_t n : kSizes) {
    registerPairs(n, "bullet_dbvt", true);
    registerPairs(n, "bullet_dbvt_immediate", false);
  }
}

}  // namespace simdphys::bench
