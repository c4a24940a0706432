// The one BVH traversal, included inside a namespace per path (the reference namespace, and each
// SIMD target's namespace in simd/bvh_query.cpp), so that the SIMD node expansion inlines into
// it. No include guard, by design (Highway's "-inl" idiom). The includer provides BvhNode and
// <cstdint>.

// Depth-first traversal with an explicit stack. `expand(node, stack, top)` tests the node's
// slots, handles the leaves that pass, pushes the child nodes that pass at stack[top...] and
// returns the new top. The stack has kWidth entries of slack, so an expansion may store a whole
// vector of candidates and advance by the number kept.
template <class Expand>
inline void traverseBvh(const ::simdphys::BvhNode* nodes, std::size_t nodeCount, Expand&& expand) {
  using ::simdphys::BvhNode;
  if (nodeCount == 0) return;
  alignas(64) std::uint32_t stack[BvhNode::kStackSize + BvhNode::kWidth];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    --top;
    top = expand(nodes[stack[top]], stack, top);
  }
}
