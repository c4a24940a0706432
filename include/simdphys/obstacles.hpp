// Static obstacles: the one set of immovable solids that everything a World moves collides with
// (particles now; cloth and rigid bodies share it). Planes are half-spaces, solid behind the
// plane (n.p + d < 0); spheres, AABBs and OBBs are closed solids. Obstacles are tested in the
// order they were added, and the first surface a path enters is the one it meets (ties go to the
// earlier obstacle).
#pragma once

#include <cstddef>
#include <span>
#include <variant>
#include <vector>

#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/handle.hpp"

namespace simdphys {

template <class T>
using ObstacleShapeT = std::variant<PlaneT<T>, SphereT<T>, AabbT<T>, ObbT<T>>;
using ObstacleShape = ObstacleShapeT<float>;

class Obstacles {
 public:
  // Adds an obstacle and returns its handle. Throws Error naming the call and the obstacle if the
  // shape is invalid (validate() of primitives.hpp: finite, in range, unit normals, orthonormal
  // axes) and changes nothing.
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
  // particle may end a step in.
  bool inside(const Vec3f& p) const;

 private:
  std::vector<ObstacleShape> shapes_;
  HandleTable handles_;
};

}  // namespace simdphys
