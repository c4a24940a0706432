// The octree: build, update, box and sphere queries, and culling through it.
#include "simdphys/scene/octree.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "classify.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "src/core/on_path.hpp"
#include "src/views.hpp"

namespace simdphys {
namespace {

constexpr std::uint32_t kPadId = ~0u;
constexpr float kInf = std::numeric_limits<float>::infinity();

bool overlaps(const Aabb& a, const Aabb& b) {
  return a.min.x() <= b.max.x() && b.min.x() <= a.max.x() && a.min.y() <= b.max.y() &&
         b.min.y() <= a.max.y() && a.min.z() <= b.max.z() && b.min.z() <= a.max.z();
}

bool contains(const Aabb& outer, const Aabb& inner) {
  return (outer.min.array() <= inner.min.array()).all() &&
         (inner.max.array() <= outer.max.array()).all();
}

Aabb emptyBox() { return {Vec3f::Constant(kInf), Vec3f::Constant(-kInf)}; }

// (a + b) / 2 as a sum of halves, which cannot overflow (a + b can, past FLT_MAX).
Vec3f halfSum(const Vec3f& a, const Vec3f& b) { return a * 0.5f + b * 0.5f; }

// Octant k of a cell: bit 0 picks the upper half in x, bit 1 in y, bit 2 in z. The halves share
// the midpoint exactly, so the octants tile the cell without gaps.
Aabb octant(const Aabb& cell, int k) {
  const Vec3f mid = halfSum(cell.min, cell.max);
  Aabb o = cell;
  for (int a = 0; a < 3; ++a) (k >> a & 1 ? o.min[a] : o.max[a]) = mid[a];
  return o;
}

}  // namespace

void Octree::build(const BoundsStream& boxes, const OctreeOptions& options) {
  if (options.maxLeafSize == 0 || options.maxDepth < 0 || options.maxDepth > 20)
    throw Error("Octree::build: maxLeafSize must be >= 1 and maxDepth in [0, 20]");
  options_ = options;
  nodes_.clear();
  outside_.clear();
  boxes_.resize(boxes.size());
  source_.resize(boxes.size());
  Aabb all = emptyBox();
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    boxes_[i] = boxes[i];
    source_[i] = source(boxes, i);
    all.min = all.min.cwiseMin(boxes_[i].min);
    all.max = all.max.cwiseMax(boxes_[i].max);
  }
  if (boxes.size() == 0) all = {Vec3f::Zero(), Vec3f::Zero()};
  // A cube, so that octants stay cubes; its half side a little over the largest half extent.
  // Centre and half side come from halves, which cannot overflow; the cube is cut to the float
  // range, which it passes only around boxes spanning more than FLT_MAX (outside the supported
  // range), so the octants' midpoints stay finite whatever the boxes.
  const Vec3f c = halfSum(all.min, all.max);
  const float half = (all.max * 0.5f - all.min * 0.5f).maxCoeff() * (1 + 1e-5f) + 1e-30f;
  const float big = std::numeric_limits<float>::max();
  Node root;
  root.cell = {(c.array() - half).max(-big), (c.array() + half).min(big)};
  nodes_.push_back(std::move(root));
  for (std::uint32_t i = 0; i < boxes_.size(); ++i) {
    if (contains(nodes_[0].cell, boxes_[i]))
      nodes_[0].ids.push_back(i);
    else
      outside_.push_back(i);  // rounding of the cube's corners; normally empty after a build
  }
  split(0);
  for (int a = 0; a < 6; ++a) packed_[a] = Stream<float>(a < 3 ? 0.0f : -kInf);
  refitAndPack();
}

// Splits a leaf that holds too many objects, handing each to every octant it overlaps, and
// recurses. Splitting stops at maxDepth, or when no octant would hold fewer objects than the
// parent (boxes larger than the octants would only be copied eight times).
void Octree::split(std::uint32_t n) {
  if (nodes_[n].ids.size() <= options_.maxLeafSize || nodes_[n].depth >= options_.maxDepth) return;
  std::array<std::vector<std::uint32_t>, 8> parts;
  std::size_t largest = 0;
  for (int k = 0; k < 8; ++k) {
    const Aabb cell = octant(nodes_[n].cell, k);
    for (std::uint32_t id : nodes_[n].ids)
      if (overlaps(cell, boxes_[id])) parts[k].push_back(id);
    largest = std::max(largest, parts[k].size());
  }
  if (largest >= nodes_[n].ids.size()) return;
  const auto first = std::uint32_t(nodes_.size());
  for (int k = 0; k < 8; ++k) {
    Node child;
    child.cell = octant(nodes_[n].cell, k);
    child.depth = nodes_[n].depth + 1;
    child.ids = std::move(parts[k]);
    nodes_.push_back(std::move(child));
  }
  nodes_[n].firstChild = first;
  nodes_[n].ids = {};
  for (int k = 0; k < 8; ++k) split(first + k);
}

void Octree::update(std::span<const std::uint32_t> moved, const BoundsStream& boxes) {
  if (boxes.size() != boxes_.size())
    throw Error("Octree::update: the stream has " + std::to_string(boxes.size()) +
                " boxes, the tree " + std::to_string(boxes_.size()));
  for (std::uint32_t id : moved)
    if (id >= boxes_.size())
      throw Error("Octree::update: id " + std::to_string(id) + " is out of range");
  for (std::uint32_t id : moved) {
    // Out of the leaves its old box overlapped (the book's Remove), then in where it is now.
    std::erase(outside_, id);
    forLeaves(boxes_[id], [&](Node& leaf) { std::erase(leaf.ids, id); });
    boxes_[id] = boxes[id];
    source_[id] = source(boxes, id);
    insert(id);
  }
  refitAndPack();
}

std::array<float, 6> Octree::source(const BoundsStream& b, std::size_t i) {
  using F = fields::Bounds;
  return {b.field(F::cx)[i], b.field(F::cy)[i], b.field(F::cz)[i],
          b.field(F::ex)[i], b.field(F::ey)[i], b.field(F::ez)[i]};
}

template <class F>
void Octree::forLeaves(const Aabb& box, F visit) {
  if (nodes_.empty()) return;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const std::uint32_t n = stack.back();
    stack.pop_back();
    if (!overlaps(nodes_[n].cell, box)) continue;
    if (nodes_[n].firstChild == 0)
      visit(nodes_[n]);
    else
      for (int k = 0; k < 8; ++k) stack.push_back(nodes_[n].firstChild + k);
  }
}

// Into every leaf whose cell the box overlaps, or the outside list.
void Octree::insert(std::uint32_t id) {
  if (!contains(nodes_[0].cell, boxes_[id]))
    outside_.push_back(id);
  else
    forLeaves(boxes_[id], [id](Node& leaf) { leaf.ids.push_back(id); });
}

Aabb Octree::refit(std::uint32_t n) {
  Aabb content = emptyBox();
  auto grow = [&content](const Aabb& b) {
    content.min = content.min.cwiseMin(b.min);
    content.max = content.max.cwiseMax(b.max);
  };
  if (nodes_[n].firstChild == 0)
    for (std::uint32_t id : nodes_[n].ids) grow(boxes_[id]);
  else
    for (int k = 0; k < 8; ++k) grow(refit(nodes_[n].firstChild + k));
  nodes_[n].content = content;
  return content;
}

// Leaves in depth-first order, each from a multiple of kStreamPad, so a subtree is one range.
void Octree::pack(std::uint32_t n, std::uint32_t& at) {
  Node& node = nodes_[n];
  node.packedBegin = at;
  if (node.firstChild == 0) {
    for (std::size_t e = 0; e < node.ids.size(); ++e) {
      for (int a = 0; a < 6; ++a) packed_[a][at + e] = source_[node.ids[e]][a];
      packedIds_[at + e] = node.ids[e];
    }
    at += std::uint32_t(paddedSize(node.ids.size()));
  } else {
    for (int k = 0; k < 8; ++k) pack(node.firstChild + k, at);
  }
  node.packedEnd = at;
}

void Octree::refitAndPack() {
  refit(0);
  std::size_t total = paddedSize(outside_.size());
  for (const Node& node : nodes_)
    if (node.firstChild == 0) total += paddedSize(node.ids.size());
  for (Stream<float>& s : packed_) s.resize(0), s.resize(total);  // all padding first
  packedIds_.assign(total, kPadId);
  std::uint32_t at = 0;
  pack(0, at);
  outsideBegin_ = at;
  for (std::size_t e = 0; e < outside_.size(); ++e) {
    for (int a = 0; a < 6; ++a) packed_[a][at + e] = source_[outside_[e]][a];
    packedIds_[at + e] = outside_[e];
  }
}

std::size_t Octree::entryCount() const {
  std::size_t n = outside_.size();
  for (const Node& node : nodes_) n += node.ids.size();
  return n;
}

int Octree::depth() const {
  int d = 0;
  for (const Node& node : nodes_) d = std::max(d, node.depth);
  return d;
}

// ---- queries ---------------------------------------------------------------------------------

template <class NodeTest, class ObjectTest>
std::vector<std::uint32_t> Octree::collect(NodeTest nodeTest, ObjectTest objectTest) const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t id : outside_)
    if (objectTest(boxes_[id])) out.push_back(id);
  std::vector<std::uint32_t> stack;
  if (!nodes_.empty()) stack.push_back(0);
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (node.content.min.x() > node.content.max.x() || !nodeTest(node.content)) continue;
    if (node.firstChild == 0) {
      for (std::uint32_t id : node.ids)
        if (objectTest(boxes_[id])) out.push_back(id);
    } else {
      for (int k = 0; k < 8; ++k) stack.push_back(node.firstChild + k);
    }
  }
  // An object in several leaves was found once per leaf.
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::uint32_t> Octree::query(const Aabb& box) const {
  validate(box, "Octree::query");
  // Closed overlap is exact and monotone: an object's box inside the content bounds can only
  // overlap the query if the bounds do.
  auto test = [&box](const Aabb& b) { return overlaps(b, box); };
  return collect(test, test);
}

std::vector<std::uint32_t> Octree::query(const Sphere& sphere) const {
  validate(sphere, "Octree::query");
  // The object test's distance can only grow from the bounds to an object inside them, but its
  // tolerance term grows with it: the bounds are tested with the radius widened by far more
  // than that term's change (16 eps of the distance), so they never reject a passing object.
  const Sphere wider{sphere.center, sphere.radius * (1 + 1e-5f) + 1e-30f};
  return collect([&wider](const Aabb& b) { return intersects(wider, b); },
                 [&sphere](const Aabb& b) { return intersects(sphere, b); });
}

// ---- culling ---------------------------------------------------------------------------------

// The objects of packed range [begin, end) that pass the test, on the active path, marked seen.
void Octree::cullRange(const Frustum& f, std::uint32_t begin, std::uint32_t end,
                       std::vector<std::uint32_t>& scratch,
                       std::vector<std::uint64_t>& seen) const {
  const std::size_t n = end - begin;
  if (n == 0) return;
  auto at = [&](int a) { return packed_[a].data() + begin; };
  selectOnPath(
      simd::BoundsView{{at(0), at(1), at(2), at(3), at(4), at(5)}, n, n}, scratch,
      [&](std::uint32_t i) {
        return f.intersectsBox({at(0)[i], at(1)[i], at(2)[i]}, {at(3)[i], at(4)[i], at(5)[i]});
      },
      [&](const auto& v, std::uint32_t* out) { return simd::cullBounds(planes(f), v, out); });
  for (std::uint32_t local : scratch) detail::markSeen(seen, packedIds_[begin + local]);
}

std::size_t Octree::cull(const Frustum& f, std::vector<std::uint32_t>& visible) const {
  validate(f, "Octree::cull");
  std::vector<std::uint64_t> seen((boxes_.size() + 63) / 64, 0);
  std::vector<std::uint32_t> scratch, stack;
  if (!nodes_.empty()) stack.push_back(0);
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (node.packedBegin == node.packedEnd) continue;  // no objects below
    const auto side = detail::classify(f, node.content.min, node.content.max);
    if (side == detail::FrustumSide::kOutside) continue;
    if (side == detail::FrustumSide::kInside) {
      for (std::uint32_t e = node.packedBegin; e < node.packedEnd; ++e)
        if (packedIds_[e] != kPadId) detail::markSeen(seen, packedIds_[e]);
    } else if (node.firstChild == 0) {
      cullRange(f, node.packedBegin, node.packedEnd, scratch, seen);
    } else {
      for (int k = 0; k < 8; ++k) stack.push_back(node.firstChild + k);
    }
  }
  cullRange(f, outsideBegin_, std::uint32_t(packedIds_.size()), scratch, seen);
  detail::seenToIds(seen, visible);
  return visible.size();
}

}  // namespace simdphys
