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

struct Range {
  std::uint32_t begin, end;
  Bounds box;
  int splits;  // binary splits from the root, for the depth limit
  std::uint32_t count() const { return end - begin; }
};

class Builder {
 public:
  Builder(const BoxStream& b, std::vector<BvhNode>& nodes) : boxes_(b), nodes_(nodes) {
    std::size_t n = b.size();
    ids_.resize(n);
    centroid_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      ids_[i] = i;
      // Twice the centre: only ordering matters, and the halving would round.
      centroid_[i] = {b.minX()[i] + b.maxX()[i], b.minY()[i] + b.maxY()[i],
                      b.minZ()[i] + b.maxZ()[i]};
    }
  }

  int build() {
    Range all{0, std::uint32_t(ids_.size()), {}, 0};
    for (std::uint32_t i = 0; i < all.end; ++i) all.box.grow(primBounds(i));
    return buildNode(all);
  }

 private:
  Bounds primBounds(std::uint32_t id) const {
    Bounds b;
    b.lo = {boxes_.minX()[id], boxes_.minY()[id], boxes_.minZ()[id]};
    b.hi = {boxes_.maxX()[id], boxes_.maxY()[id], boxes_.maxZ()[id]};
    return b;
  }

  // Returns the depth (in nodes) of the subtree it builds at nodes_.back().
  int buildNode(const Range& range) {
    std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.emplace_back();
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
    BvhNode node;
    int depth = 1;
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const Bounds& b = k < used ? kids[k].box : Bounds{};
      node.minX[k] = b.lo[0], node.minY[k] = b.lo[1], node.minZ[k] = b.lo[2];
      node.maxX[k] = b.hi[0], node.maxY[k] = b.hi[1], node.maxZ[k] = b.hi[2];
      node.child[k] = BvhNode::kEmpty;
      if (k >= used) continue;
      if (kids[k].count() == 1) {
        node.child[k] = BvhNode::kLeaf | ids_[kids[k].begin];
      } else {
        node.child[k] = std::uint32_t(nodes_.size());
        depth = std::max(depth, 1 + buildNode(kids[k]));
      }
    }
    nodes_[index] = node;
    return depth;
  }

  std::pair<Range, Range> split(const Range& r) {
    Bounds cb;
    for (std::uint32_t i = r.begin; i < r.end; ++i) cb.grow(centroid_[ids_[i]]);
    if (r.splits < kMaxSahDepth)
      if (auto s = sahSplit(r, cb)) return *s;
    return medianSplit(r, cb);
  }

  std::optional<std::pair<Range, Range>> sahSplit(const Range& r, const Bounds& cb) {
    struct Bin {
      Bounds box;
      std::uint32_t count = 0;
    };
    float bestCost = kInf;
    int bestAxis = -1, bestBin = 0;
    std::array<float, 3> scale{};
    std::array<std::array<Bin, kBins>, 3> bins;
    for (int a = 0; a < 3; ++a) {
      float extent = cb.hi[a] - cb.lo[a];
      if (!(extent > 0)) continue;
      scale[a] = kBins * (1 - 1e-6f) / extent;
    }
    for (std::uint32_t i = r.begin; i < r.end; ++i) {
      std::uint32_t id = ids_[i];
      Bounds pb = primBounds(id);
      for (int a = 0; a < 3; ++a) {
        if (scale[a] == 0) continue;
        Bin& bin = bins[a][binOf(centroid_[id][a], cb.lo[a], scale[a])];
        bin.box.grow(pb);
        ++bin.count;
      }
    }
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
    auto mid = std::partition(ids_.begin() + r.begin, ids_.begin() + r.end, [&](std::uint32_t id) {
      return binOf(centroid_[id][a], cb.lo[a], scale[a]) < bestBin;
    });
    std::uint32_t m = std::uint32_t(mid - ids_.begin());
    Range left{r.begin, m, {}, r.splits + 1}, right{m, r.end, {}, r.splits + 1};
    for (int k = 0; k < kBins; ++k) (k < bestBin ? left : right).box.grow(bins[a][k].box);
    return std::pair{left, right};
  }

  // Halves the range at the median centroid on the widest axis (ties by id): always balanced.
  std::pair<Range, Range> medianSplit(const Range& r, const Bounds& cb) {
    int a = 0;
    for (int k = 1; k < 3; ++k)
      if (cb.hi[k] - cb.lo[k] > cb.hi[a] - cb.lo[a]) a = k;
    std::uint32_t m = r.begin + r.count() / 2;
    std::nth_element(ids_.begin() + r.begin, ids_.begin() + m, ids_.begin() + r.end,
                     [&](std::uint32_t i, std::uint32_t j) {
                       float ci = centroid_[i][a], cj = centroid_[j][a];
                       return ci < cj || (ci == cj && i < j);
                     });
    Range left{r.begin, m, {}, r.splits + 1}, right{m, r.end, {}, r.splits + 1};
    for (std::uint32_t i = left.begin; i < left.end; ++i) left.box.grow(primBounds(ids_[i]));
    for (std::uint32_t i = right.begin; i < right.end; ++i) right.box.grow(primBounds(ids_[i]));
    return {left, right};
  }

  static int binOf(float c, float lo, float scale) {
    return std::clamp(int((c - lo) * scale), 0, kBins - 1);
  }

  const BoxStream& boxes_;
  std::vector<BvhNode>& nodes_;
  std::vector<std::uint32_t> ids_;
  std::vector<std::array<float, 3>> centroid_;
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
