// Static obstacles: the one set of immovable shapes that everything a World moves collides with
// (particles now; cloth and rigid bodies share it). Planes are half-spaces, solid behind the
// plane (n.p + d < 0); spheres, AABBs and OBBs are closed solids; a triangle mesh is a two-sided
// surface (no inside), found through its own MeshBvh. Obstacles are tested in the order they
// were added, and the first surface a path enters is the one it meets (ties go to the earlier
// obstacle, within a mesh to the lower triangle id).
//
// Beyond kFewObstacles bounded obstacles (all but planes), they are found through one Bvh over
// their bounds, built when the set changed, rather than each tested by every particle.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <variant>
#include <vector>

#include "simdphys/bvh.hpp"
#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/handle.hpp"
#include "simdphys/mesh_bvh.hpp"

namespace simdphys {

// A mesh obstacle shares its tree with whoever else holds it (a Scene's model, another world).
using MeshObstacle = std::shared_ptr<const MeshBvh>;

template <class T>
using ObstacleShapeT = std::variant<PlaneT<T>, SphereT<T>, AabbT<T>, ObbT<T>, MeshObstacle>;
using ObstacleShape = ObstacleShapeT<float>;

class Obstacles {
 public:
  static constexpr std::size_t kFewObstacles = 8;

  // Adds an obstacle and returns its handle. Throws Error naming the call and the obstacle if the
  // shape is invalid (validate() of primitives.hpp: finite, in range, unit normals, orthonormal
  // axes; a null mesh) and changes nothing.
  Handle add(const ObstacleShape& shape);
  // Removes an obstacle; the last one takes its place in the order. Throws Error if stale.
  void remove(Handle obstacle);
  bool contains(Handle obstacle) const { return handles_.contains(obstacle); }
  const ObstacleShape& operator[](Handle obstacle) const;

  std::size_t size() const { return shapes_.size(); }
  bool empty() const { return shapes_.empty(); }
  // In the order they are tested.
  std::span<const ObstacleShape> shapes() const { return shapes_; }

  // True when p lies strictly inside a solid (behind a plane, within a sphere or a box): what no
  // particle may end a step in. Meshes have no inside.
  bool inside(const Vec3f& p) const;

  // The tree over the bounded obstacles when there are more than kFewObstacles of them, else
  // null; its ids index bounded(). Built by update(), which the world calls before a step.
  const Bvh* tree() const { return treeBuilt_ ? &tree_ : nullptr; }
  // Indices (into shapes()) of the bounded obstacles, in order, and of the planes.
  std::span<const std::uint32_t> bounded() const { return bounded_; }
  // With the tree, the boxes it holds, one per bounded obstacle: its box grown past the rounding
  // of the exact tests (no computed test meets the obstacle from outside it).
  std::span<const Aabb> boxes() const { return boxes_; }
  std::span<const std::uint32_t> planes() const { return planes_; }
  void update();
  // Changes whenever an obstacle is added or removed.
  std::uint64_t version() const { return version_; }

 private:
  std::vector<ObstacleShape> shapes_;
  friend struct detail::Snapshot;
  HandleTable handles_;
  std::vector<std::uint32_t> bounded_, planes_;
  std::vector<Aabb> boxes_;
  Bvh tree_;
  bool treeBuilt_ = false, dirty_ = false;
  std::uint64_t version_ = 1;
};

}  // namespace simdphys
