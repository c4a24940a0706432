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

#include "bench/peers/bullet.hpp"

namespace simdphys::bench {
namespace {

constexpr std::size_t kSizes[] = {100'000, 1'000'000};

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
  btBroadphaseProxy* proxy(std::size_t i) const { return proxies_[i]; }

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

// aabb_pairs: the broadphase persistent across iterations, as a world keeps it from step to step
// (and as aabb_bench.cpp keeps its PairFinder), built outside the timed loop. Timed per
// iteration: one step of a world whose boxes are set anew, setAabb for each of the N proxies,
// then calculateOverlappingPairs, and the pair cache read. Only the conversion of the pairs to box
// indices for the checksum is left out of the timing.
// Deferred mode (Bullet's choice for large scenes) collides the dynamic tree with itself on every
// calculateOverlappingPairs; a proxy set every step stays in the dynamic tree (it would move to
// the fixed tree only after STAGECOUNT steps without a setAabb), so each step is a complete pair
// search over the N boxes, the work PairFinder does. setAabb with an unchanged box inside its
// leaf's volume leaves the leaf as it is, so the leaves stay the exact boxes (createProxy inserts
// them unfattened) and the pairs are exact. Immediate mode is not timed here: with unchanged boxes
// its step searches nothing (setAabb collides a proxy only when its leaf changes).
void registerPairs(std::size_t n) {
  registerOnce("aabb_pairs", "bullet_dbvt", "peer", n, [n](benchmark::State& state) {
    const auto& w = aabbWorkload(n);
    const auto& ref = aabbReference(n);
    std::vector<std::pair<btVector3, btVector3>> boxes;
    for (std::size_t i = 0; i < w.boxes.size(); ++i)
      boxes.emplace_back(toBullet(w.boxes[i].min), toBullet(w.boxes[i].max));
    Dbvt dbvt(w.boxes, /*deferred=*/true);
    auto step = [&] {
      for (std::size_t i = 0; i < boxes.size(); ++i)
        dbvt->setAabb(dbvt.proxy(i), boxes[i].first, boxes[i].second, nullptr);
      dbvt->calculateOverlappingPairs(nullptr);
      return &dbvt->getOverlappingPairCache()->getOverlappingPairArray();
    };
    step();  // warm-up: the pair cache and the trees reach their size
    std::vector<Pair> pairs;
    for (auto _ : state) {
      const btBroadphasePairArray& found = *step();
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
    state.counters["checksum_ok"] = workloads::pairChecksum(pairs, n) == ref.checksum ? 1 : 0;
    checkExact(state, pairs.size(), ref.pairs);
  });
}

}  // namespace

void registerBulletBenchmarks() {
  for (std::size_t n : kSizes) registerQuery(n);
  for (std::size_t n : kSizes) registerPairs(n);
}

}  // namespace simdphys::bench
