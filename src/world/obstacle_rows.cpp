// The obstacles as rows (obstacle_rows.hpp).
#include "src/world/obstacle_rows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "simd/kernels.hpp"
#include "src/reference/particles/step-inl.hpp"

namespace simdphys::detail {

namespace {

// The row's box: its centre and reach per axis, grown (core::ObstacleRow::lo).
void growBox(core::ObstacleRow& r) {
  const float inf = std::numeric_limits<float>::infinity();
  const float* v = r.v;
  float center[3] = {}, reach[3] = {inf, inf, inf};
  for (int k = 0; k < 3; ++k) {
    switch (r.kind) {
      case core::ObstacleRow::kPlane:  // a half-space: nothing is culled
        break;
      case core::ObstacleRow::kSphere:
        center[k] = v[k], reach[k] = v[3];
        break;
      case core::ObstacleRow::kAabb:
      case core::ObstacleRow::kMesh:  // v holds the box (a mesh's: its vertices'), min then max
        center[k] = 0.5f * (v[k] + v[3 + k]), reach[k] = 0.5f * (v[3 + k] - v[k]);
        break;
      case core::ObstacleRow::kObb:  // the box's extent along world axis k
        center[k] = v[k];
        reach[k] =
            std::abs(v[6 + k]) * v[3] + std::abs(v[9 + k]) * v[4] + std::abs(v[12 + k]) * v[5];
        break;
    }
  }
  const float size = std::max({reach[0], reach[1], reach[2], std::abs(center[0]),
                               std::abs(center[1]), std::abs(center[2])});
  for (int k = 0; k < 3; ++k) {
    const float grown = reach[k] * 1.001f + 1e-3f * size + 1e-6f;
    r.lo[k] = center[k] - grown, r.hi[k] = center[k] + grown;
  }
}

// The tree's SIMD walk, without the checks of Bvh::query (the kernels' boxes are finite), one
// walk a box.
void treeNear(const void* context, const float* lo, const float* hi, std::size_t n,
              std::vector<std::uint32_t>& rows) {
  const Obstacles& o = *static_cast<const Obstacles*>(context);
  const std::span<const BvhNode> nodes = o.tree()->nodes();
  thread_local std::vector<std::uint32_t> found;
  found.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const simd::Box box{lo[i], lo[n + i], lo[2 * n + i], hi[i], hi[n + i], hi[2 * n + i]};
    if (!(box.minX <= box.maxX && box.minY <= box.maxY && box.minZ <= box.maxZ)) continue;
    simd::bvhQuery(nodes.data(), nodes.size(), box, found);
  }
  rows.assign(o.planes().begin(), o.planes().end());
  for (std::uint32_t k : found) rows.push_back(o.bounded()[k]);
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());  // boxes found by several lanes
}

// The reference's entry into a mesh (step-inl.hpp), lane by lane.
void meshEntry(const void* context, std::uint32_t row, std::size_t n, const float* x0,
               const float* dir, const float* live, float* s, float* normal, float* hit) {
  const Obstacles& o = *static_cast<const Obstacles*>(context);
  const MeshObstacle& mesh = std::get<MeshObstacle>(o.shapes()[row]);
  for (std::size_t i = 0; i < n; ++i) {
    hit[i] = 0;
    if (live[i] == 0) continue;
    const Vec3f from(x0[i], x0[n + i], x0[2 * n + i]), d(dir[i], dir[n + i], dir[2 * n + i]);
    const auto e = reference::entryOf<float>(mesh, from, d);
    if (!e) continue;
    hit[i] = 1, s[i] = e->s;
    for (int k = 0; k < 3; ++k) normal[k * n + i] = e->normal[k];
  }
}

}  // namespace

core::ObstacleRow rowOf(const ObstacleShape& shape) {
  core::ObstacleRow r{};
  const auto put = [&](int at, const Vec3f& v) {
    for (int k = 0; k < 3; ++k) r.v[at + k] = v[k];
  };
  if (const auto* p = std::get_if<Plane>(&shape)) {
    r.kind = core::ObstacleRow::kPlane, put(0, p->normal), r.v[3] = p->d;
  } else if (const auto* s = std::get_if<Sphere>(&shape)) {
    r.kind = core::ObstacleRow::kSphere, put(0, s->center), r.v[3] = s->radius;
  } else if (const auto* b = std::get_if<Aabb>(&shape)) {
    r.kind = core::ObstacleRow::kAabb, put(0, b->min), put(3, b->max);
  } else if (const auto* o = std::get_if<Obb>(&shape)) {
    r.kind = core::ObstacleRow::kObb, put(0, o->center), put(3, o->halfExtents);
    for (int c = 0; c < 3; ++c) put(6 + 3 * c, o->axes.col(c));
  } else {
    const Aabb box = std::get<MeshObstacle>(shape)->mesh().bounds();
    r.kind = core::ObstacleRow::kMesh, put(0, box.min), put(3, box.max);
  }
  growBox(r);
  return r;
}

std::vector<core::ObstacleRow> obstacleRows(const Obstacles& obstacles) {
  std::vector<core::ObstacleRow> rows;
  for (const ObstacleShape& shape : obstacles.shapes()) rows.push_back(rowOf(shape));
  return rows;
}

std::optional<core::ObstacleQueries> obstacleQueries(const Obstacles& obstacles) {
  core::ObstacleQueries q{&obstacles, nullptr, nullptr};
  if (obstacles.tree()) q.near = treeNear;
  for (const ObstacleShape& shape : obstacles.shapes())
    if (std::holds_alternative<MeshObstacle>(shape)) q.meshEntry = meshEntry;
  if (!q.near && !q.meshEntry) return std::nullopt;
  return q;
}

}  // namespace simdphys::detail
