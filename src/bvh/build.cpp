// Binned-SAH build straight into 8-wide nodes, and refit.
#include <algorithm>
#include <array>
#include <limits>
#include <optional>

#include "simdphys/bvh.hpp"

namespace simdphys {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kBins = 16;
// Below this many binary splits from the root, SAH is trusted; deeper, the build switches to
// median splits, which bound the depth (and so the traversal stack) on adversarial inputs.
constexpr int kMaxSahDepth = 40;
// Ranges this small are split at the median: as good as SAH for a handful of boxes, and cheap.
constexpr std::uint32_t kSmallRange = 16;
// Subtrees above this many primitives are built as parallel tasks.
constexpr std::uint32_t kParallelGrain = 8192;

struct Bounds {
  std::array<float, 3> lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
  void grow(const Bounds& b) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
  }
  void grow(const std::array<float, 3>& p) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  float halfArea() const {
    float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    return dx < 0 ? 0 : dx * dy + dy * dz + dz * dx;
  }
};

// A primitive as the builder moves it: its box and id in 32 bytes, partitioned in place, so
// every pass over a range reads memory in order (Embree's PrimRef).
struct PrimRef {
  std::array<float, 3> lo;
  std::uint32_t id;
  std::array<float, 3> hi;
  float pad;
  // Twice the centre: only the ordering matters, and halving would round.
  float centroid(int a) const { return lo[a] + hi[a]; }
};
static_assert(sizeof(PrimRef) == 32);

struct Range {
  std::uint32_t begin, end;
  Bounds box;   // of the primitives
  Bounds cbox;  // of their centroids
  int splits;   // binary splits from the root, for the depth limit
  std::uint32_t count() const { return end - begin; }
};

class Builder {
 public:
  Builder(const BoxStream& b, std::vector<BvhNode>& nodes) : nodes_(nodes), prims_(b.size()) {
    for (std::uint32_t i = 0; i < prims_.size(); ++i)
      prims_[i] = {
          {b.minX()[i], b.minY()[i], b.minZ()[i]}, i, {b.maxX()[i], b.maxY()[i], b.maxZ()[i]}, 0};
  }

  int build() {
    Range all{0, std::uint32_t(prims_.size()), {}, {}, 0};
    for (const PrimRef& p : prims_) grow(all, p);
    int depth = 0;
#pragma omp parallel
#pragma omp single
    depth = buildNode(all, nodes_);
    return depth;
  }

 private:
  static void grow(Range& r, const PrimRef& p) {
    for (int a = 0; a < 3; ++a) {
      r.box.lo[a] = std::min(r.box.lo[a], p.lo[a]), r.box.hi[a] = std::max(r.box.hi[a], p.hi[a]);
      float c = p.centroid(a);
      r.cbox.lo[a] = std::min(r.cbox.lo[a], c), r.cbox.hi[a] = std::max(r.cbox.hi[a], c);
    }
  }

  // Builds the subtree of `range` at the end of `out`, children after their parent, depth first;
  // returns its depth in nodes. Large child ranges are built as OpenMP tasks, each into a list of
  // its own, then appended in slot order with their node indices moved: the tree is the same,
  // node for node, whatever the number of threads.
  int buildNode(const Range& range, std::vector<BvhNode>& out) {
    const std::uint32_t index = std::uint32_t(out.size());
    out.emplace_back();
    std::array<Range, BvhNode::kWidth> kids;
    int used = 1;
    kids[0] = range;
    while (used < BvhNode::kWidth) {
      int best = -1;
      for (int k = 0; k < used; ++k)
        if (kids[k].count() > 1 && (best < 0 || kids[k].box.halfArea() > kids[best].box.halfArea()))
          best = k;
      if (best < 0) break;
      auto [left, right] = split(kids[best]);
      kids[best] = left;
      kids[used++] = right;
    }
    std::array<std::vector<BvhNode>, BvhNode::kWidth> subtrees;
    std::array<int, BvhNode::kWidth> depths{};
    for (int k = 0; k < used; ++k) {
      if (kids[k].count() > kParallelGrain) {
#pragma omp task default(shared) firstprivate(k)
        depths[k] = buildNode(kids[k], subtrees[k]);
      }
    }
    BvhNode node;
    int depth = 1;
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const Bounds& b = k < used ? kids[k].box : Bounds{};
      node.minX[k] = b.lo[0], node.minY[k] = b.lo[1], node.minZ[k] = b.lo[2];
      node.maxX[k] = b.hi[0], node.maxY[k] = b.hi[1], node.maxZ[k] = b.hi[2];
      node.child[k] = BvhNode::kEmpty;
      if (k >= used) continue;
      if (kids[k].count() == 1) {
        node.child[k] = BvhNode::kLeaf | prims_[kids[k].begin].id;
        continue;
      }
      node.child[k] = std::uint32_t(out.size());
      if (kids[k].count() > kParallelGrain) {
#pragma omp taskwait
        append(subtrees[k], out);
        depth = std::max(depth, 1 + depths[k]);
      } else {
        depth = std::max(depth, 1 + buildNode(kids[k], out));
      }
    }
    out[index] = node;
    return depth;
  }

  // Appends a subtree built on its own, moving its child node indices to where it lands.
  static void append(const std::vector<BvhNode>& subtree, std::vector<BvhNode>& out) {
    const std::uint32_t offset = std::uint32_t(out.size());
    for (BvhNode node : subtree) {
      for (std::uint32_t& c : node.child)
        if (c != BvhNode::kEmpty && !BvhNode::isLeaf(c)) c += offset;
      out.push_back(node);
    }
  }

  std::pair<Range, Range> split(const Range& r) {
    // Binning has a fixed cost (48 bins to clear and sweep) that small ranges do not repay.
    if (r.splits < kMaxSahDepth && r.count() > kSmallRange)
      if (auto s = sahSplit(r)) return *s;
    return medianSplit(r);
  }

  // Binned SAH over the three axes: one pass fills the bins, a second partitions the range.
  std::optional<std::pair<Range, Range>> sahSplit(const Range& r) {
    struct Bin {
      Bounds box;
      std::uint32_t count = 0;
    };
    std::array<float, 3> scale{};
    for (int a = 0; a < 3; ++a) {
      float extent = r.cbox.hi[a] - r.cbox.lo[a];
      if (extent > 0) scale[a] = kBins * (1 - 1e-6f) / extent;
    }
    std::array<std::array<Bin, kBins>, 3> bins;
    for (std::uint32_t i = r.begin; i < r.end; ++i) {
      const PrimRef& p = prims_[i];
      for (int a = 0; a < 3; ++a) {
        Bin& bin = bins[a][binOf(p.centroid(a), r.cbox.lo[a], scale[a])];
        for (int e = 0; e < 3; ++e)
          bin.box.lo[e] = std::min(bin.box.lo[e], p.lo[e]),
          bin.box.hi[e] = std::max(bin.box.hi[e], p.hi[e]);
        ++bin.count;
      }
    }
    float bestCost = kInf;
    int bestAxis = -1, bestBin = 0;
    for (int a = 0; a < 3; ++a) {
      if (scale[a] == 0) continue;
      // Right-to-left sweep stores the right cost of every split; left-to-right finds the best.
      std::array<float, kBins> rightCost{};
      Bounds acc;
      std::uint32_t n = 0;
      for (int k = kBins - 1; k > 0; --k) {
        acc.grow(bins[a][k].box);
        n += bins[a][k].count;
        rightCost[k] = n ? acc.halfArea() * float(n) : kInf;
      }
      acc = {};
      n = 0;
      for (int k = 1; k < kBins; ++k) {
        acc.grow(bins[a][k - 1].box);
        n += bins[a][k - 1].count;
        float cost = n ? acc.halfArea() * float(n) + rightCost[k] : kInf;
        if (cost < bestCost) bestCost = cost, bestAxis = a, bestBin = k;
      }
    }
    if (bestAxis < 0) return std::nullopt;
    const int a = bestAxis;
    return partition(r, [&](const PrimRef& p) {
      return binOf(p.centroid(a), r.cbox.lo[a], scale[a]) < bestBin;
    });
  }

  // Halves the range at the median centroid on the widest axis (ties by id): always balanced.
  std::pair<Range, Range> medianSplit(const Range& r) {
    int a = 0;
    for (int k = 1; k < 3; ++k)
      if (r.cbox.hi[k] - r.cbox.lo[k] > r.cbox.hi[a] - r.cbox.lo[a]) a = k;
    auto less = [a](const PrimRef& p, const PrimRef& q) {
      return p.centroid(a) < q.centroid(a) || (p.centroid(a) == q.centroid(a) && p.id < q.id);
    };
    std::uint32_t m = r.begin + r.count() / 2;
    std::nth_element(prims_.begin() + r.begin, prims_.begin() + m, prims_.begin() + r.end, less);
    const PrimRef pivot = prims_[m];
    return partition(r, [&](const PrimRef& p) { return less(p, pivot); });
  }

  // Moves the primitives that go left before the others (Hoare's scheme) and measures both
  // sides on the way.
  template <class GoesLeft>
  std::pair<Range, Range> partition(const Range& r, GoesLeft goesLeft) {
    std::uint32_t i = r.begin, j = r.end;
    Range left{r.begin, 0, {}, {}, r.splits + 1}, right{0, r.end, {}, {}, r.splits + 1};
    while (true) {
      while (i < j && goesLeft(prims_[i])) grow(left, prims_[i++]);
      while (i < j && !goesLeft(prims_[j - 1])) grow(right, prims_[--j]);
      if (i >= j) break;
      std::swap(prims_[i], prims_[j - 1]);
    }
    left.end = right.begin = i;
    return {left, right};
  }

  static int binOf(float c, float lo, float scale) {
    return std::clamp(int((c - lo) * scale), 0, kBins - 1);
  }

  std::vector<BvhNode>& nodes_;
  std::vector<PrimRef> prims_;
};

}  // namespace

void Bvh::build(const BoxStream& boxes) {
  if (boxes.size() > kMaxPrimitives)
    throw Error("Bvh::build: " + std::to_string(boxes.size()) + " boxes, more than the " +
                std::to_string(kMaxPrimitives) + " a tree can index");
  nodes_.clear();
  primitives_ = boxes.size();
  depth_ = 0;
  if (primitives_ == 0) return;
  nodes_.reserve(primitives_ / 3 + 1);  // a full tree has about n/7 nodes; SAH leaves slack
  depth_ = Builder(boxes, nodes_).build();
  // The median fallback below kMaxSahDepth splits bounds the depth; this guards that reasoning.
  if (depth_ > BvhNode::kMaxDepth)
    throw Error("Bvh::build: depth " + std::to_string(depth_) + " exceeds the traversal stack");
}

void Bvh::refit(const BoxStream& boxes) {
  if (boxes.size() != primitives_)
    throw Error("Bvh::refit: the stream has " + std::to_string(boxes.size()) +
                " boxes, the tree was built on " + std::to_string(primitives_));
  // Children always follow their parent in the array, so one backward pass sees every child
  // before its parent.
  for (std::size_t n = nodes_.size(); n-- > 0;) {
    BvhNode& node = nodes_[n];
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      std::uint32_t c = node.child[k];
      if (c == BvhNode::kEmpty) continue;
      if (BvhNode::isLeaf(c)) {
        std::uint32_t id = BvhNode::leafFirst(c);
        node.minX[k] = boxes.minX()[id], node.minY[k] = boxes.minY()[id];
        node.minZ[k] = boxes.minZ()[id], node.maxX[k] = boxes.maxX()[id];
        node.maxY[k] = boxes.maxY()[id], node.maxZ[k] = boxes.maxZ()[id];
        continue;
      }
      const BvhNode& sub = nodes_[c];
      node.minX[k] = *std::min_element(sub.minX, sub.minX + BvhNode::kWidth);
      node.minY[k] = *std::min_element(sub.minY, sub.minY + BvhNode::kWidth);
      node.minZ[k] = *std::min_element(sub.minZ, sub.minZ + BvhNode::kWidth);
      node.maxX[k] = *std::max_element(sub.maxX, sub.maxX + BvhNode::kWidth);
      node.maxY[k] = *std::max_element(sub.maxY, sub.maxY + BvhNode::kWidth);
      node.maxZ[k] = *std::max_element(sub.maxZ, sub.maxZ + BvhNode::kWidth);
    }
  }
}

}  // namespace simdphys
