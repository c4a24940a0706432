// Binned-SAH build straight into 8-wide nodes, and refit.
#include <algorithm>
#include <array>
#include <limits>

#include <omp.h>

#include "simd/kernels.hpp"
#include "simdphys/bvh.hpp"

namespace simdphys {
namespace {
using PrimRef = detail::BvhPrimRef;
using simd::BvhBox;
static_assert(sizeof(PrimRef) == 32);

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kBins = simd::kBvhBins;
// Below this many binary splits from the root, SAH is trusted; deeper, the build switches to
// median splits, which bound the depth (and so the traversal stack) on adversarial inputs.
constexpr int kMaxSahDepth = 40;
// Ranges this small are split at the median: as good as SAH for a handful of boxes, and cheap.
// Larger ones are binned, on 4 bins up to 19 primitives: on W2 that builds 5% faster than the
// median's nth_element up to 16 did, and single rays trace 5% faster (docs/bvh.md).
constexpr std::uint32_t kSmallRange = 8;
// Subtrees above this many primitives are built as parallel tasks.
constexpr std::uint32_t kParallelGrain = 8192;

// A box in the kernels' rows (x, y, z, -); the default is empty.
struct Bounds : BvhBox {
  Bounds() : BvhBox{{kInf, kInf, kInf, kInf}, {-kInf, -kInf, -kInf, -kInf}} {}
  explicit Bounds(const BvhBox& b) : BvhBox(b) {}
  void grow(const BvhBox& b) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
  }
  void grow(const float* p) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  float halfArea() const {
    float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    return dx < 0 ? 0 : dx * dy + dy * dz + dz * dx;
  }
};

struct Range {
  std::uint32_t begin, end;
  Bounds box;   // of the primitives
  Bounds cbox;  // of their centroids
  int splits;   // binary splits from the root, for the depth limit
  std::uint32_t count() const { return end - begin; }
};

class Builder {
 public:
  Builder(AlignedVector<PrimRef> prims, const BvhBuildOptions& options,
          AlignedVector<BvhNode>& nodes)
      : nodes_(nodes), prims_(std::move(prims)), options_(options) {}

  // The primitive ids in leaf order (leaves reference ranges of it).
  AlignedVector<std::uint32_t> order() const {
    AlignedVector<std::uint32_t> ids;
    ids.reserve(prims_.size());
    for (const PrimRef& p : prims_) ids.push_back(p.id());
    return ids;
  }

  int build() {
    Range all{0, std::uint32_t(prims_.size()), {}, {}, 0};
    simd::bvhBounds(prims_.data(), prims_.size(), all.box, all.cbox);
    int depth = 0;
#pragma omp parallel
#pragma omp single
    {
      // One thread builds straight into the node list: a task's own list and the copy that
      // splices it in would only cost time (the tree is the same either way).
      parallel_ = omp_get_num_threads() > 1;
      depth = buildNode(all, nodes_);
    }
    return depth;
  }

 private:
  // Builds the subtree of `range` at the end of `out`, children after their parent, depth first;
  // returns its depth in nodes. Large child ranges are built as OpenMP tasks, each into a list of
  // its own, then appended in slot order with their node indices moved: the tree is the same,
  // node for node, whatever the number of threads.
  int buildNode(const Range& range, AlignedVector<BvhNode>& out) {
    const std::uint32_t index = std::uint32_t(out.size());
    out.emplace_back();
    std::array<Range, BvhNode::kWidth> kids;
    // Whether a child fitting a leaf has been judged not worth splitting.
    std::array<bool, BvhNode::kWidth> settled{};
    int used = 1;
    kids[0] = range;
    while (used < BvhNode::kWidth) {
      // Children too large for a leaf are split first, largest surface first; then, while slots
      // remain, the largest child that a leaf could hold is split if the SAH says its two halves
      // cost less to test than it does (a split inside a node adds no node to visit).
      int best = -1;
      bool mustSplit = false;
      for (int k = 0; k < used; ++k) {
        const bool must = kids[k].count() > options_.maxLeafSize;
        const bool may = kids[k].count() > 1 && !settled[k];
        if (!must && !may) continue;
        if (best < 0 || must > mustSplit ||
            (must == mustSplit && kids[k].box.halfArea() > kids[best].box.halfArea()))
          best = k, mustSplit = must;
      }
      if (best < 0) break;
      Range& parent = kids[best];
      simd::BvhSides sides;
      split(parent, sides);
      const std::uint32_t left = std::uint32_t(sides.left), right = parent.count() - left;
      if (!mustSplit &&
          leafCost(Bounds(sides.box[0]), left) + leafCost(Bounds(sides.box[1]), right) >=
              leafCost(parent.box, parent.count())) {
        settled[best] = true;
        continue;
      }
      // The halves written in place: a range is 80 bytes, and copies of pairs of them were a
      // twentieth of the build.
      const std::uint32_t middle = parent.begin + left;
      kids[used++] = Range{middle, parent.end, Bounds(sides.box[1]), Bounds(sides.centroids[1]),
                           parent.splits + 1};
      parent = Range{parent.begin, middle, Bounds(sides.box[0]), Bounds(sides.centroids[0]),
                     parent.splits + 1};
    }
    std::array<AlignedVector<BvhNode>, BvhNode::kWidth> subtrees;
    std::array<int, BvhNode::kWidth> depths{};
    auto asTask = [&](int k) { return parallel_ && kids[k].count() > kParallelGrain; };
    for (int k = 0; k < used; ++k) {
      if (asTask(k)) {
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
      if (kids[k].count() <= options_.maxLeafSize) {
        // A box tree's one-primitive leaf names the primitive; others reference a range of the
        // order, renumbered by Bvh::build once the leaves are aligned.
        const std::uint32_t first =
            options_.maxLeafSize == 1 ? prims_[kids[k].begin].id() : kids[k].begin;
        node.child[k] = BvhNode::kLeaf | (kids[k].count() - 1) << BvhNode::kCountShift | first;
        continue;
      }
      node.child[k] = std::uint32_t(out.size());
      if (asTask(k)) {
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
  static void append(const AlignedVector<BvhNode>& subtree, AlignedVector<BvhNode>& out) {
    const std::uint32_t offset = std::uint32_t(out.size());
    for (BvhNode node : subtree) {
      for (std::uint32_t& c : node.child)
        if (c != BvhNode::kEmpty && !BvhNode::isLeaf(c)) c += offset;
      out.push_back(node);
    }
  }

  // The SAH cost of testing `count` primitives in `box` as one leaf: its surface times the blocks
  // of leafAlign primitives they take.
  float leafCost(const Bounds& box, std::uint32_t count) const {
    const std::uint32_t blocks = (count + options_.leafAlign - 1) / options_.leafAlign;
    return box.halfArea() * float(blocks);
  }

  // Reorders the range into two non-empty sides, measured in `sides`.
  void split(const Range& r, simd::BvhSides& sides) {
    // Binning has a fixed cost (two sets of 48 bins to clear and merge, then the sweep) that small
    // ranges do not repay.
    if (r.splits < kMaxSahDepth && r.count() > kSmallRange && sahSplit(r, sides)) return;
    medianSplit(r, sides);
  }

  // Binned SAH over the three axes: one pass fills the bins, a second partitions the range.
  // False if no axis splits it.
  bool sahSplit(const Range& r, simd::BvhSides& sides) {
    simd::BvhBinFrame frame{};
    // Embree's bin count, 4 + N / 20 up to the most: small ranges pay for fewer bins to clear,
    // merge and sweep, and lose little choice.
    const int bins = int(std::min<std::uint32_t>(kBins, 4 + r.count() / 20));
    frame.bins = bins;
    for (int a = 0; a < 3; ++a) {
      const float extent = r.cbox.hi[a] - r.cbox.lo[a];
      const float scale = float(bins) * (1 - 1e-6f) / extent;
      frame.origin[a] = r.cbox.lo[a];
      // An extent below 16 / FLT_MAX would give an infinite scale, and 0 * inf a NaN: not split on.
      frame.scale[a] = extent > 0 && scale < kInf ? scale : 0;
    }
    simd::BvhBins binned;
    simd::bvhBin(prims_.data() + r.begin, r.count(), frame, binned);
    float bestCost = kInf;
    int bestAxis = -1, bestBin = 0;
    for (int a = 0; a < 3; ++a) {
      if (frame.scale[a] == 0) continue;
      // Right-to-left sweep stores the right cost of every split; left-to-right finds the best.
      std::array<float, kBins> rightCost{};
      Bounds acc;
      std::uint32_t n = 0;
      for (int k = bins - 1; k > 0; --k) {
        acc.grow(binned.box[a][k]);
        n += binned.count[a][k];
        rightCost[k] = n ? acc.halfArea() * float(n) : kInf;
      }
      acc = {};
      n = 0;
      for (int k = 1; k < bins; ++k) {
        acc.grow(binned.box[a][k - 1]);
        n += binned.count[a][k - 1];
        float cost = n ? acc.halfArea() * float(n) + rightCost[k] : kInf;
        if (cost < bestCost) bestCost = cost, bestAxis = a, bestBin = k;
      }
    }
    if (bestAxis < 0) return false;
    simd::bvhPartition(prims_.data() + r.begin, r.count(), frame, bestAxis, bestBin, sides);
    // The partition repeats the binning's arithmetic, so neither side is empty; should a platform
    // ever round the two differently, the median split still makes progress.
    return sides.left != 0 && sides.left != r.count();
  }

  // Halves the range at the median centroid on the widest axis (ties by id): always balanced.
  void medianSplit(const Range& r, simd::BvhSides& sides) {
    int a = 0;
    for (int k = 1; k < 3; ++k)
      if (r.cbox.hi[k] - r.cbox.lo[k] > r.cbox.hi[a] - r.cbox.lo[a]) a = k;
    auto less = [a](const PrimRef& p, const PrimRef& q) {
      return p.centroid(a) < q.centroid(a) || (p.centroid(a) == q.centroid(a) && p.id() < q.id());
    };
    const std::uint32_t half = r.count() / 2;
    std::nth_element(prims_.begin() + r.begin, prims_.begin() + r.begin + half,
                     prims_.begin() + r.end, less);
    // nth_element leaves the smaller half before the median (the order is total): measure them.
    simd::bvhBounds(prims_.data() + r.begin, half, sides.box[0], sides.centroids[0]);
    simd::bvhBounds(prims_.data() + r.begin + half, r.count() - half, sides.box[1],
                    sides.centroids[1]);
    sides.left = half;
  }

  AlignedVector<BvhNode>& nodes_;
  AlignedVector<PrimRef> prims_;
  BvhBuildOptions options_;
  bool parallel_ = false;
};

// What validate() accepts, without building its message for each of a million boxes.
bool wellFormed(const Aabb& b) {
  return b.min.allFinite() && b.max.allFinite() && (b.min.array() <= b.max.array()).all();
}

// Places every multi-primitive leaf in a new order, in node order (so leaves a traversal meets
// together lie together), packed into blocks of `align` slots without straddling one: each node's
// leaves, largest first, go to the first of its blocks with room, starting with the block the
// previous node left open. W2's leaves of 2, 4, 6 and 8 then take a quarter fewer blocks than one
// block each. A slot no leaf takes repeats its block's first primitive.
AlignedVector<std::uint32_t> alignLeaves(AlignedVector<BvhNode>& nodes,
                                         const AlignedVector<std::uint32_t>& order,
                                         std::uint32_t align) {
  constexpr std::uint32_t kFree = BvhNode::kEmpty;
  AlignedVector<std::uint32_t> aligned;
  aligned.reserve(order.size() + order.size() / 4);
  std::uint32_t open = 0;  // the first block a node may fill
  // Slots taken in blocks open, open + 1, ...: a node adds at most a block a leaf.
  std::array<std::uint32_t, BvhNode::kWidth + 1> used{};
  for (BvhNode& node : nodes) {
    std::array<int, BvhNode::kWidth> leaves;
    int n = 0;
    for (int k = 0; k < BvhNode::kWidth; ++k)
      if (node.child[k] != BvhNode::kEmpty && BvhNode::isLeaf(node.child[k])) leaves[n++] = k;
    if (n == 0) continue;
    if (align == 1) {  // no blocks: each leaf where the last one ended
      for (int i = 0; i < n; ++i) {
        std::uint32_t& c = node.child[leaves[i]];
        const std::uint32_t first = BvhNode::leafFirst(c), at = std::uint32_t(aligned.size());
        aligned.insert(aligned.end(), order.begin() + first,
                       order.begin() + first + BvhNode::leafCount(c));
        c = (c & ~BvhNode::kFirstMask) | at;
      }
      continue;
    }
    std::stable_sort(leaves.begin(), leaves.begin() + n, [&](int a, int b) {
      return BvhNode::leafCount(node.child[a]) > BvhNode::leafCount(node.child[b]);
    });
    const std::uint32_t blocks = std::uint32_t(aligned.size()) / align;
    // Of the blocks before, only the last stays open to this node: a node's leaves then lie in
    // consecutive blocks (leafSpan).
    if (blocks > open + 1) used[0] = used[blocks - 1 - open], open = blocks - 1;
    for (int i = 0; i < n; ++i) {
      std::uint32_t& c = node.child[leaves[i]];
      const std::uint32_t first = BvhNode::leafFirst(c), count = BvhNode::leafCount(c);
      std::uint32_t b = 0;
      while (open + b < aligned.size() / align && used[b] + count > align) ++b;
      if (open + b == aligned.size() / align)
        aligned.resize(aligned.size() + align, kFree), used[b] = 0;
      const std::uint32_t at = (open + b) * align + used[b];
      std::copy(order.begin() + first, order.begin() + first + count, aligned.begin() + at);
      used[b] += count;
      c = (c & ~BvhNode::kFirstMask) | at;
    }
  }
  for (std::size_t s = 0; s < aligned.size(); ++s)
    if (aligned[s] == kFree) aligned[s] = aligned[s / align * align];
  return aligned;
}

// Sets each child node's leafSpan in its parent (bvh_types.hpp): the blocks of `align` primitives
// its leaf children lie in, when those are consecutive (alignLeaves places them so); align 0: no
// blocks.
void spanLeaves(AlignedVector<BvhNode>& nodes, std::uint32_t align) {
  for (BvhNode& node : nodes)
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      node.leafSpan[k] = BvhNode::kEmpty;
      const std::uint32_t c = node.child[k];
      if (align == 0 || c == BvhNode::kEmpty || BvhNode::isLeaf(c)) continue;
      std::array<std::uint32_t, BvhNode::kWidth> blocks;
      int n = 0;
      for (std::uint32_t g : nodes[c].child)
        if (g != BvhNode::kEmpty && BvhNode::isLeaf(g)) blocks[n++] = BvhNode::leafFirst(g) / align;
      std::sort(blocks.begin(), blocks.begin() + n);
      n = int(std::unique(blocks.begin(), blocks.begin() + n) - blocks.begin());
      if (n != 0 && blocks[n - 1] - blocks[0] + 1 == std::uint32_t(n))
        node.leafSpan[k] = std::uint32_t(n - 1) << BvhNode::kCountShift | blocks[0];
    }
}

}  // namespace

void Bvh::build(const BoxStream& boxes) {
  AlignedVector<PrimRef> prims;  // reserved, not sized: a sized vector is zeroed first
  prims.reserve(boxes.size());
  using F = fields::Box;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    prims.push_back(
        PrimRef({boxes.field(F::minX)[i], boxes.field(F::minY)[i], boxes.field(F::minZ)[i]},
                {boxes.field(F::maxX)[i], boxes.field(F::maxY)[i], boxes.field(F::maxZ)[i]}, i));
  buildFrom(std::move(prims), BvhBuildOptions{}, "Bvh::build");
}

void Bvh::build(std::span<const Aabb> bounds, const BvhBuildOptions& options) {
  if (options.maxLeafSize < 1 || options.maxLeafSize > 16)
    throw Error("Bvh::build: maxLeafSize " + std::to_string(options.maxLeafSize) +
                " is outside [1, 16]");
  if (options.leafAlign != 1 && options.leafAlign < options.maxLeafSize)
    throw Error("Bvh::build: leafAlign " + std::to_string(options.leafAlign) +
                " is neither 1 nor at least maxLeafSize");
  if (bounds.size() > kMaxPrimitives)  // checked before the loop below narrows the index
    throw Error("Bvh::build: " + std::to_string(bounds.size()) + " primitives, more than the " +
                std::to_string(kMaxPrimitives) + " a tree can index");
  AlignedVector<PrimRef> prims;
  prims.reserve(bounds.size());
  for (std::uint32_t i = 0; i < bounds.size(); ++i) {
    const Aabb& b = bounds[i];
    if (!wellFormed(b)) validate(b, "Bvh::build: bounds " + std::to_string(i));
    prims.push_back(
        PrimRef({b.min.x(), b.min.y(), b.min.z()}, {b.max.x(), b.max.y(), b.max.z()}, i));
  }
  buildFrom(std::move(prims), options, "Bvh::build");
}

void Bvh::buildFrom(AlignedVector<PrimRef> prims, const BvhBuildOptions& options,
                    const char* where) {
  if (prims.size() > kMaxPrimitives)
    throw Error(std::string(where) + ": " + std::to_string(prims.size()) +
                " primitives, more than the " + std::to_string(kMaxPrimitives) +
                " a tree can index");
  nodes_.clear();
  order_.clear();
  options_ = options;
  primitives_ = prims.size();
  depth_ = 0;
  if (primitives_ == 0) return;
  // Room for the nodes up front (reserved pages cost nothing until written): W2's tree has n/16
  // nodes for leaves of up to 8, where n/24 made the vector grow, copying 5.6 MB, mid-build.
  nodes_.reserve(primitives_ / options.maxLeafSize + 1);
  Builder builder(std::move(prims), options, nodes_);
  depth_ = builder.build();
  // The median fallback below kMaxSahDepth splits bounds the depth; this guards that reasoning.
  if (depth_ > BvhNode::kMaxDepth)
    throw Error(std::string(where) + ": depth " + std::to_string(depth_) +
                " exceeds the traversal stack");
  if (options.maxLeafSize > 1) order_ = alignLeaves(nodes_, builder.order(), options.leafAlign);
  spanLeaves(nodes_, options.maxLeafSize > 1 && options.leafAlign > 1 ? options.leafAlign : 0);
  if (order_.size() > kMaxPrimitives)
    throw Error(std::string(where) + ": the aligned leaves need " + std::to_string(order_.size()) +
                " slots, more than the " + std::to_string(kMaxPrimitives) + " a tree can index");
}

namespace {
// One backward pass: children always follow their parent in the array, so every child is seen
// before its parent. `leafBox(reference, k)` returns a leaf slot's bounds.
template <class LeafBox>
void refitNodes(AlignedVector<BvhNode>& nodes, LeafBox leafBox) {
  for (std::size_t n = nodes.size(); n-- > 0;) {
    BvhNode& node = nodes[n];
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      std::uint32_t c = node.child[k];
      if (c == BvhNode::kEmpty) continue;
      Bounds b;
      if (BvhNode::isLeaf(c)) {
        b = leafBox(c);
      } else {
        const BvhNode& sub = nodes[c];
        for (int s = 0; s < BvhNode::kWidth; ++s) {
          const float lo[3] = {sub.minX[s], sub.minY[s], sub.minZ[s]};
          const float hi[3] = {sub.maxX[s], sub.maxY[s], sub.maxZ[s]};
          b.grow(lo), b.grow(hi);
        }
      }
      node.minX[k] = b.lo[0], node.minY[k] = b.lo[1], node.minZ[k] = b.lo[2];
      node.maxX[k] = b.hi[0], node.maxY[k] = b.hi[1], node.maxZ[k] = b.hi[2];
    }
  }
}
}  // namespace

void Bvh::refit(const BoxStream& boxes) {
  if (boxes.size() != primitives_)
    throw Error("Bvh::refit: the stream has " + std::to_string(boxes.size()) +
                " boxes, the tree was built on " + std::to_string(primitives_));
  requireBoxTree("Bvh::refit(BoxStream)");
  refitNodes(nodes_, [&](std::uint32_t c) {
    const std::uint32_t id = BvhNode::leafFirst(c);
    using F = fields::Box;
    Bounds b;
    const float lo[3] = {boxes.field(F::minX)[id], boxes.field(F::minY)[id],
                         boxes.field(F::minZ)[id]};
    const float hi[3] = {boxes.field(F::maxX)[id], boxes.field(F::maxY)[id],
                         boxes.field(F::maxZ)[id]};
    b.grow(lo), b.grow(hi);
    return b;
  });
}

void Bvh::refit(std::span<const Aabb> bounds) {
  if (bounds.size() != primitives_)
    throw Error("Bvh::refit: " + std::to_string(bounds.size()) + " bounds, the tree was built on " +
                std::to_string(primitives_));
  for (std::size_t i = 0; i < bounds.size(); ++i)
    if (!wellFormed(bounds[i])) validate(bounds[i], "Bvh::refit: bounds " + std::to_string(i));
  const bool direct = options_.maxLeafSize == 1;
  refitNodes(nodes_, [&](std::uint32_t c) {
    const std::uint32_t first = BvhNode::leafFirst(c);
    Bounds b;
    for (std::uint32_t i = 0; i < BvhNode::leafCount(c); ++i) {
      const Aabb& p = bounds[direct ? first : order_[first + i]];
      b.grow(p.min.data()), b.grow(p.max.data());
    }
    return b;
  });
}

void Bvh::requireBoxTree(const char* where) const {
  if (options_.maxLeafSize != 1)
    throw Error(std::string(where) +
                ": the tree has leaves of several primitives (a mesh's); query it through its "
                "owner");
}

}  // namespace simdphys
