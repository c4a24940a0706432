// The one BVH walk (Embree's: one traversal written once, templated on the node test), for every
// query that descends the tree: box queries, the mesh's rays one at a time and in packets, the
// scene's rays, the frustum cull. Included inside a namespace per path (the reference's in src/,
// each SIMD target's in simd/), so that the path's node and leaf tests inline into it. No include
// guard, by design (Highway's "-inl" idiom). The includer provides BvhNode (bvh_types.hpp),
// <cstdint> and <limits>.

// Depth first with a fixed-size stack: the build bounds the depth (BvhNode::kMaxDepth), and each
// level leaves at most kWidth - 1 siblings on it. The walker gives the stack's entries and the
// tests:
//   Entry                      a reference, with what the node test learned (an entry distance,
//                              per-lane distances); `Walker::ref(entry)` is the reference.
//   skip(entry)                true if a popped entry is no longer worth visiting (the closest
//                              hit found since it was pushed is nearer than its box).
//   leaf(entry)                a leaf reached: tests its primitives; true stops the walk.
//   expand(node, entry, stack, top)  tests the node's slots and pushes the children that pass at
//                              stack[top...] (the first to visit last), advancing `top`; it may
//                              handle leaves itself rather than push them. It may instead hand the
//                              child to visit first back in `entry` and return true: that child is
//                              visited at once (the ray walk's nearest child, just tested against
//                              the bound). The stack has kWidth entries of slack, so it may store
//                              a whole vector of candidates and advance by the number kept.
// `root` is where the walk starts: the root node, or a subtree handed over by another walk.
template <class Walker>
inline void walkBvh(const ::simdphys::BvhNode* nodes, std::size_t nodeCount, Walker& walker,
                    const typename Walker::Entry& root) {
  using ::simdphys::BvhNode;
  using Entry = typename Walker::Entry;
  if (nodeCount == 0) return;
  alignas(64) Entry stack[BvhNode::kStackSize + BvhNode::kWidth];
  int top = 0;
  stack[top++] = root;
  while (top > 0) {
    Entry e = stack[--top];  // a copy: the children may reuse the slot
    if (walker.skip(e)) continue;
    for (;;) {
      const std::uint32_t ref = Walker::ref(e);
      if (BvhNode::isLeaf(ref)) {
        if (walker.leaf(e)) return;
        break;
      }
      if (!walker.expand(nodes[ref], e, stack, top)) break;
    }
  }
}

// A walk whose entries are bare node references and whose node test handles the leaves that pass
// (box queries, the cull): no entry is skipped and none is a leaf.
struct NodeWalk {
  using Entry = std::uint32_t;
  static std::uint32_t ref(Entry e) { return e; }
  static bool skip(Entry) { return false; }
  static bool leaf(Entry) { return false; }
};

// The ray walk: nearest child first, and an entry farther than the closest hit found since it was
// pushed is skipped. `core.expand(node, bound, refs, dists)` writes the children whose box the ray
// enters before `bound` (their references and scaled entry distances, in any order) and returns
// their number; `core.leaf(reference)` tests a leaf's primitives and returns true to stop
// (any-hit); `core.bound()` is the current culling distance.
template <class Core>
class RayWalk {
 public:
  struct Entry {
    std::uint32_t ref;
    float t;
  };
  explicit RayWalk(Core& core) : core_(core) {}

  static std::uint32_t ref(const Entry& e) { return e.ref; }
  bool skip(const Entry& e) const { return e.t > core_.bound(); }
  bool leaf(const Entry& e) { return core_.leaf(e.ref); }
  bool expand(const ::simdphys::BvhNode& n, Entry& e, Entry* stack, int& top) {
    using ::simdphys::BvhNode;
    alignas(64) std::uint32_t refs[2 * BvhNode::kWidth];
    alignas(64) float dists[2 * BvhNode::kWidth];
    const int count = core_.expand(n, core_.bound(), refs, dists);
    if (count == 0) return false;
    if (count == 1) {
      e = {refs[0], dists[0]};
      return true;
    }
    // Insertion sort, farthest first, straight onto the stack; the nearest is visited now.
    const int base = top;
    for (int k = 0; k < count; ++k) {
      int j = top++;
      while (j > base && stack[j - 1].t < dists[k]) stack[j] = stack[j - 1], --j;
      stack[j] = {refs[k], dists[k]};
    }
    e = stack[--top];
    return true;
  }

 private:
  Core& core_;
};

// The ray walk from `start`: the root, or (a packet handing a ray over) a node or leaf reference,
// which is visited whatever its distance.
template <class Core>
inline void traverseRay(const ::simdphys::BvhNode* nodes, std::size_t nodeCount, Core& core,
                        std::uint32_t start = 0) {
  RayWalk<Core> walk(core);
  walkBvh(nodes, nodeCount, walk, {start, -std::numeric_limits<float>::infinity()});
}
