// MeshBvh: the build into triangle blocks, refit, and the single queries with their reference
// path (ray streams: stream_tracing.cpp).
#include "simdphys/mesh_bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "simd/kernels.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/raycast.hpp"
#include "src/bvh/scalar_walk.hpp"
#include "src/mesh/mesh_internal.hpp"

// Overlap and linetest queries call these per triangle: their definitions, so that they inline.
#include "src/reference/geometry3d/intersect-inl.hpp"
#include "src/reference/geometry3d/raycast-inl.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

// ---- the reference path: the same walk, a scalar core -------------------------------------
namespace reference {

template <class Sink>
class RayCore {
 public:
  RayCore(std::span<const TriangleBlock> blocks, const detail::TraversalRay& ray, Sink& sink)
      : blocks_(blocks), ray_(ray), sink_(sink) {
    // The scalar triangle test's ray: the frame the kernels use (its direction is not read).
    watertight_.origin = {ray.ox, ray.oy, ray.oz};
    watertight_.kx = ray.kx, watertight_.ky = ray.ky, watertight_.kz = ray.kz;
    watertight_.sx = ray.sx, watertight_.sy = ray.sy, watertight_.sz = ray.sz;
  }

  float bound() const { return sink_.bound(); }

  int expand(const BvhNode& n, float bound, std::uint32_t* refs, float* dists) const {
    return expandRay(n, ray_, bound, refs, dists);
  }

  bool leaf(std::uint32_t ref) {
    const TriangleBlock& b = blocks_[TriangleBlock::of(ref)];
    const std::uint32_t begin = TriangleBlock::firstLane(ref);
    for (std::uint32_t l = begin; l < begin + BvhNode::leafCount(ref); ++l) {
      const Triangle tri{{b.v[0][0][l], b.v[0][1][l], b.v[0][2][l]},
                         {b.v[1][0][l], b.v[1][1][l], b.v[1][2][l]},
                         {b.v[2][0][l], b.v[2][1][l], b.v[2][2][l]}};
      const auto h = intersectTriangle(watertight_, tri, sink_.bound());
      if (!h) continue;
      if constexpr (Sink::kAnyHit) {
        sink_.found = true;
        return true;
      } else {
        sink_.offer(h->t, b.id[l]);
      }
    }
    return false;
  }

 private:
  std::span<const TriangleBlock> blocks_;
  const detail::TraversalRay& ray_;
  WatertightRay watertight_;
  Sink& sink_;
};

ElementHit closestHit(const Bvh& bvh, std::span<const TriangleBlock> blocks,
                      const detail::TraversalRay& ray) {
  Closest closest(ray.tMax);
  RayCore<Closest> core(blocks, ray, closest);
  traverseRay(bvh.nodes().data(), bvh.nodes().size(), core);
  return closest.result();
}

bool anyHit(const Bvh& bvh, std::span<const TriangleBlock> blocks,
            const detail::TraversalRay& ray) {
  Any any{ray.tMax};
  RayCore<Any> core(blocks, ray, any);
  traverseRay(bvh.nodes().data(), bvh.nodes().size(), core);
  return any.found;
}
}  // namespace reference

// ---- rays ------------------------------------------------------------------------------------

namespace {
std::string at(std::string_view where, std::size_t i) {
  return std::string(where) + ": element " + std::to_string(i);
}

void validateRay(const Ray& ray, float tMax, const std::string& where) {
  detail::requireFiniteField(ray.origin, where, "origin");
  // A direction is not a point: any finite length (a linecast's is the segment, up to 2e18 on
  // an axis); t is in its units.
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(ray.direction[a]))
      throw Error(where + ": direction." + "xyz"[a] + " is " + std::to_string(ray.direction[a]) +
                  ", not finite");
  if ((ray.direction.array() == 0).all()) throw Error(where + ": the direction is zero");
  if (!(tMax >= 0)) throw Error(where + ": tMax " + std::to_string(tMax) + " is negative or NaN");
}

// The kernels take rays as a stream: one ray is a stream of one.
template <class Kernel>
void withRaysView(const Ray& ray, const float& tMax, Kernel kernel) {
  const float o[3] = {ray.origin.x(), ray.origin.y(), ray.origin.z()};
  const float d[3] = {ray.direction.x(), ray.direction.y(), ray.direction.z()};
  kernel(simd::RaysView{{o, o + 1, o + 2, d, d + 1, d + 2, &tMax}, 1, 1});
}

detail::TraversalRay traversal(const Ray& r, float tMax) {
  return detail::traversalRay(r.origin.x(), r.origin.y(), r.origin.z(), r.direction.x(),
                              r.direction.y(), r.direction.z(), tMax);
}
}  // namespace

void RayStream::push(const Ray& ray, float tMax) {
  validateRay(ray, tMax, at("RayStream::push", size()));
  append({ray.origin.x(), ray.origin.y(), ray.origin.z(), ray.direction.x(), ray.direction.y(),
          ray.direction.z(), tMax});
}

Ray RayStream::operator[](std::size_t i) const {
  return {{value(0, i), value(1, i), value(2, i)}, {value(3, i), value(4, i), value(5, i)}};
}

ElementHit MeshBvh::raycast(const Ray& ray, float tMax) const {
  validateRay(ray, tMax, "MeshBvh::raycast");
  if (referencePathActive()) return reference::closestHit(bvh_, blocks_, traversal(ray, tMax));
  ElementHit h;
  withRaysView(ray, tMax, [&](const simd::RaysView& v) {
    simd::meshClosestHits(meshView(bvh_, blocks_), v, &h.index, &h.t);
  });
  return h;
}

bool MeshBvh::occluded(const Ray& ray, float tMax) const {
  validateRay(ray, tMax, "MeshBvh::occluded");
  if (referencePathActive()) return reference::anyHit(bvh_, blocks_, traversal(ray, tMax));
  std::uint8_t hit = 0;
  withRaysView(ray, tMax, [&](const simd::RaysView& v) {
    simd::meshAnyHits(meshView(bvh_, blocks_), v, &hit);
  });
  return hit != 0;
}

// ---- query bounds ----------------------------------------------------------------------------

namespace {
Aabb boundsOf(const Sphere& s) {
  return {s.center.array() - s.radius, s.center.array() + s.radius};
}
Aabb boundsOf(const Aabb& b) { return b; }
Aabb boundsOf(const Obb& b) {
  const Vec3f reach = b.axes.cwiseAbs() * b.halfExtents;
  return {b.center - reach, b.center + reach};
}
Aabb boundsOf(const Segment& s) { return {s.start.cwiseMin(s.end), s.start.cwiseMax(s.end)}; }
Aabb boundsOf(const Triangle& t) {
  return {t.a.cwiseMin(t.b).cwiseMin(t.c), t.a.cwiseMax(t.b).cwiseMax(t.c)};
}

// The bounds of any shape in the supported range lie within 4 kMaxCoordinate (an OBB's centre
// plus three half extents); a query beyond is rejected, so the widened box below stays finite.
constexpr float kMaxQueryBound = 4 * kMaxCoordinate;

void requireInReach(const Aabb& bounds, const char* where) {
  const float reach = std::max(bounds.min.cwiseAbs().maxCoeff(), bounds.max.cwiseAbs().maxCoeff());
  if (reach <= kMaxQueryBound) return;
  std::ostringstream msg;
  msg << where << ": the query reaches " << reach
      << ", outside the supported range (|coordinate| and sizes <= " << kMaxCoordinate << ")";
  throw Error(msg.str());
}
}  // namespace

// ---- segments --------------------------------------------------------------------------------

// raycast.hpp's linecast: the ray from start along end - start (not normalised) up to t = 1, then
// t turned into a distance. A point-like segment crosses nothing.
ElementHit MeshBvh::linecast(const Segment& s) const {
  validate(s, "MeshBvh::linecast");
  requireInReach(boundsOf(s), "MeshBvh::linecast");
  if (detail::rays::isPointSegment(s)) return {};
  ElementHit h = raycast(Ray{s.start, s.direction()}, 1.0f);
  if (h.hit()) h.t *= s.length();
  return h;
}

// A crossing, or a triangle the segment touches in its plane (raycast.hpp's linetest), among the
// triangles whose bounds meet the segment's.
bool MeshBvh::linetest(const Segment& s) const {
  validate(s, "MeshBvh::linetest");
  requireInReach(boundsOf(s), "MeshBvh::linetest");
  if (!detail::rays::isPointSegment(s) && occluded(Ray{s.start, s.direction()}, 1.0f)) return true;
  bool found = false;
  reference::overlappingLeaves(
      bvh_.nodes(), boundsOf(s), [&](std::uint32_t first, std::uint32_t count) {
        for (std::uint32_t i = 0; i < count && !found; ++i)
          found = simdphys::linetest(mesh_.triangle(bvh_.order()[first + i]), s);
      });
  return found;
}

// ---- overlap ---------------------------------------------------------------------------------

// The tests of intersect.hpp accept shapes up to kGeometryTolerance * scale apart, scale bounded
// by the shapes' sizes and their distance; the query's bounds are widened by several times that
// for the largest scale in play (the query, the mesh's extent and its longest edge), so the tree
// never culls a triangle the exact test would accept.
template <class Shape>
std::vector<std::uint32_t> MeshBvh::overlappingShape(const Shape& shape, const char* where) const {
  validate(shape, where);
  const Aabb bounds = boundsOf(shape);
  requireInReach(bounds, where);
  std::vector<std::uint32_t> ids;
  if (mesh_.size() == 0) return ids;
  const float scale = (bounds.max - bounds.min).maxCoeff() + bounds.min.cwiseAbs().maxCoeff() +
                      bounds.max.cwiseAbs().maxCoeff() + extent_;
  const float margin = 8 * kGeometryTolerance<float> * scale;
  const Aabb wide{bounds.min.array() - margin, bounds.max.array() + margin};
  reference::overlappingLeaves(bvh_.nodes(), wide, [&](std::uint32_t first, std::uint32_t count) {
    for (std::uint32_t i = 0; i < count; ++i) {
      const std::uint32_t id = bvh_.order()[first + i];
      if (intersects(mesh_.triangle(id), shape)) ids.push_back(id);
    }
  });
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<std::uint32_t> MeshBvh::overlapping(const Sphere& s) const {
  return overlappingShape(s, "MeshBvh::overlapping(Sphere)");
}
std::vector<std::uint32_t> MeshBvh::overlapping(const Aabb& b) const {
  return overlappingShape(b, "MeshBvh::overlapping(Aabb)");
}
std::vector<std::uint32_t> MeshBvh::overlapping(const Obb& b) const {
  return overlappingShape(b, "MeshBvh::overlapping(Obb)");
}
std::vector<std::uint32_t> MeshBvh::overlapping(const Triangle& t) const {
  return overlappingShape(t, "MeshBvh::overlapping(Triangle)");
}

// ---- build and refit -------------------------------------------------------------------------

namespace {
AlignedVector<Aabb> triangleBounds(const Mesh& m) {
  AlignedVector<Aabb> b;
  b.reserve(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) b.push_back(boundsOf(m.triangle(i)));
  return b;
}

float extentOf(const Mesh& m) {
  float e = 0;
  for (const Vec3f& v : m.vertices) e = std::max(e, v.cwiseAbs().maxCoeff());
  return 2 * e;
}
}  // namespace

MeshBvh::MeshBvh(Mesh mesh) : mesh_(std::move(mesh)) {
  // The builder's primitives made from the triangles as they are validated (one pass over them;
  // an array of bounds between would be another, over 24 bytes a triangle): a valid triangle's
  // bounds are well formed.
  detail::validateVertices(mesh_, "MeshBvh");
  if (mesh_.size() > Bvh::kMaxPrimitives)
    throw Error("MeshBvh: " + std::to_string(mesh_.size()) + " triangles, more than the " +
                std::to_string(Bvh::kMaxPrimitives) + " a tree can index");
  AlignedVector<detail::BvhPrimRef> prims;  // reserved, not sized: a sized vector is zeroed first
  prims.reserve(mesh_.size());
  for (std::uint32_t i = 0; i < mesh_.size(); ++i) {
    detail::validateTriangle(mesh_, i, "MeshBvh");
    const Aabb b = boundsOf(mesh_.triangle(i));
    prims.push_back(detail::BvhPrimRef({b.min.x(), b.min.y(), b.min.z()},
                                       {b.max.x(), b.max.y(), b.max.z()}, i));
  }
  bvh_.buildFrom(std::move(prims), {kLeafSize, kLeafSize}, "MeshBvh");
  extent_ = extentOf(mesh_);
  fillBlocks();
}

std::span<const std::uint8_t> MeshBvh::activeEdges() const {
  std::call_once(*activeEdges_.once, [this] { activeEdges_.bits = simdphys::activeEdges(mesh_); });
  return activeEdges_.bits;
}

void MeshBvh::refit(std::span<const Vec3f> vertices) {
  if (vertices.size() != mesh_.vertices.size())
    throw Error("MeshBvh::refit: " + std::to_string(vertices.size()) + " vertices, the mesh has " +
                std::to_string(mesh_.vertices.size()));
  Mesh moved{{vertices.begin(), vertices.end()}, mesh_.triangles};
  moved.validate("MeshBvh::refit");  // before anything changes: a throw leaves the tree as it was
  mesh_.vertices = std::move(moved.vertices);
  bvh_.refit(triangleBounds(mesh_));
  extent_ = extentOf(mesh_);
  activeEdges_ = LazyActiveEdges();
  fillBlocks();
}

void MeshBvh::fillBlocks() {
  const auto order = bvh_.order();
  // Appended one by one, each filled where it lies, rather than resized: resizing would zero 30 MB
  // in a pass of its own only to overwrite it.
  blocks_.clear();
  blocks_.reserve(order.size() / TriangleBlock::kWidth);
  for (std::size_t b = 0; b < order.size() / TriangleBlock::kWidth; ++b) {
    TriangleBlock& block = blocks_.emplace_back();
    for (int l = 0; l < TriangleBlock::kWidth; ++l) {
      const std::uint32_t id = order[b * TriangleBlock::kWidth + l];
      const auto& corners = mesh_.triangles[id];
      for (int q = 0; q < 3; ++q) {
        const Vec3f& v = mesh_.vertices[corners[q]];
        for (int k = 0; k < 3; ++k) block.v[q][k][l] = v[k];
      }
      block.id[l] = id;
    }
  }
}

}  // namespace simdphys
