// The one BVH traversal, included inside a namespace per path (the reference namespace, and each
// SIMD target's namespace in simd/bvh_query.cpp), so that the SIMD child test inlines into it.
// No include guard, by design (Highway's "-inl" idiom). The includer provides BvhNode and
// <cstdint>.

// Visits, depth first, every leaf whose slot passes `test` on all its ancestors. `test(node)`
// returns the bit mask of the node's slots that pass; `visit(childReference)` gets each leaf.
template <class Test, class Visit>
inline void traverseBvh(const ::simdphys::BvhNode* nodes, std::size_t nodeCount, Test&& test,
                        Visit&& visit) {
  using ::simdphys::BvhNode;
  if (nodeCount == 0) return;
  std::uint32_t stack[BvhNode::kStackSize];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& node = nodes[stack[--top]];
    for (std::uint32_t mask = test(node); mask != 0; mask &= mask - 1) {
      std::uint32_t child = node.child[__builtin_ctz(mask)];
      if (BvhNode::isLeaf(child))
        visit(child);
      else
        stack[top++] = child;
    }
  }
}
