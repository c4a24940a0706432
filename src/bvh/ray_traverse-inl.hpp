// The one ray traversal of the BVH, included inside a namespace per path (src/mesh/ for the
// reference, each SIMD target's namespace in simd/bvh_ray.cpp), so that the path's node and leaf
// tests inline into it. No include guard, by design (Highway's "-inl" idiom). The includer
// provides BvhNode, <cstdint>, <limits> and detail::TraversalRay (src/bvh/mesh_ray.hpp).

// The closest hit under W2's rule: the smallest t, and among the hits within kTieWindow of it the
// smallest id. The hits inside the window are kept (up to kMaxTies; beyond, the farthest, then the
// largest ids, give way), since a nearer hit found later narrows the window and may drop its winner
// while keeping another. `bound` is what the traversal culls against: a hit beyond it cannot
// change the answer.
class ClosestHits {
 public:
  static constexpr int kMaxTies = 16;
  explicit ClosestHits(float tMax) : tMax_(tMax), bound_(tMax) {}
  // A ray that hits nothing (tMax = -inf), to be assigned a real one (arrays of rays in packets).
  ClosestHits() : ClosestHits(-std::numeric_limits<float>::infinity()) {}

  float bound() const { return bound_; }

  // A hit; ignored if beyond bound() (a hit tested against an older, wider bound).
  void offer(float t, std::uint32_t id) {
    if (t > bound_) return;
    if (t < tMin_) {
      tMin_ = t;
      bound_ = std::min(tMax_, t * ::simdphys::kTieWindow);
      int kept = 0;
      for (int k = 0; k < count_; ++k)
        if (ties_[k].t <= bound_) ties_[kept++] = ties_[k];
      count_ = kept;
    }
    if (count_ < kMaxTies) {
      ties_[count_++] = {t, id};
      return;
    }
    // Full: the worst entry (farthest, then largest id) gives way to a better one, so equal-t
    // ties keep the smallest ids.
    int worst = 0;
    for (int k = 1; k < count_; ++k)
      if (worse(ties_[k], ties_[worst])) worst = k;
    if (worse(ties_[worst], {t, id})) ties_[worst] = {t, id};
  }

  // The winner: id kNoHit and t = inf if nothing was hit.
  ::simdphys::MeshHit result() const {
    ::simdphys::MeshHit best;
    for (int k = 0; k < count_; ++k)
      if (ties_[k].id < best.id) best = {ties_[k].id, ties_[k].t};
    return best;
  }

 private:
  struct Tie {
    float t;
    std::uint32_t id;
  };
  static bool worse(const Tie& a, const Tie& b) { return a.t > b.t || (a.t == b.t && a.id > b.id); }
  float tMax_, bound_;
  float tMin_ = std::numeric_limits<float>::infinity();
  int count_ = 0;
  Tie ties_[kMaxTies];
};

// The two sinks of a traversal: the closest hit, and any hit (which stops at the first).
struct Closest : ClosestHits {
  using ClosestHits::ClosestHits;
  static constexpr bool kAnyHit = false;
};
struct Any {
  static constexpr bool kAnyHit = true;
  float tMax;
  bool found = false;
  float bound() const { return tMax; }
};

// Depth-first, nearest child first. `core.expand(node, bound, refs, dists)` writes the children
// whose box the ray enters before `bound` (their references and scaled entry distances, in any
// order) and returns their number; `core.leaf(reference)` tests a leaf's triangles and returns
// true to stop (any-hit); `core.bound()` is the current culling distance. A popped entry farther
// than the bound (which shrinks as hits are found) is skipped unvisited. `start` is the subtree to
// walk: the root, or (packet traversal handing a ray over) a node or leaf reference.
template <class Core>
inline void traverseRay(const ::simdphys::BvhNode* nodes, std::size_t nodeCount, Core& core,
                        std::uint32_t start = 0) {
  using ::simdphys::BvhNode;
  if (nodeCount == 0) return;
  struct Entry {
    std::uint32_t ref;
    float t;
  };
  Entry stack[BvhNode::kStackSize + BvhNode::kWidth];
  int top = 0;
  std::uint32_t ref = start;
  for (;;) {
    if (BvhNode::isLeaf(ref)) {
      if (core.leaf(ref)) return;
    } else {
      alignas(64) std::uint32_t refs[2 * BvhNode::kWidth];
      alignas(64) float dists[2 * BvhNode::kWidth];
      const int n = core.expand(nodes[ref], core.bound(), refs, dists);
      if (n == 1) {
        ref = refs[0];
        continue;
      }
      if (n > 1) {
        // Insertion sort, farthest first, straight onto the stack; the nearest is visited now.
        const int base = top;
        for (int k = 0; k < n; ++k) {
          int j = top++;
          while (j > base && stack[j - 1].t < dists[k]) stack[j] = stack[j - 1], --j;
          stack[j] = {refs[k], dists[k]};
        }
        ref = stack[--top].ref;
        continue;
      }
    }
    do {
      if (top == 0) return;
      --top;
    } while (stack[top].t > core.bound());
    ref = stack[top].ref;
  }
}
