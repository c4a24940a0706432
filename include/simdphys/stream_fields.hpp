// The fields of every stream, declared once: their order and their padding. A stream class
// (geometry3d/streams.hpp, geometry2d/streams.hpp) is a StreamSet of one of these layouts, and the
// SIMD kernels read a stream through one view type (core/view.hpp) indexed by the same names, so
// a field is named in one place. Eigen-free, so the kernels may include it.
//
// Padding makes padded lanes inert: an element made of the padding values produces no result in
// any kernel (an empty box, a sphere of radius -inf), so kernels run over whole vectors.
#pragma once

#include <cstddef>
#include <limits>

namespace simdphys::fields {

inline constexpr float kPadInf = std::numeric_limits<float>::infinity();

// Boxes as min/max corners, the layout of overlap tests. Padding: empty boxes (min = +inf,
// max = -inf), which overlap nothing.
struct Box {
  enum : std::size_t { minX, minY, minZ, maxX, maxY, maxZ, kCount };
  static constexpr float kPad[kCount] = {kPadInf, kPadInf, kPadInf, -kPadInf, -kPadInf, -kPadInf};
};

// Spheres as centre and radius. Padding: radius -inf, which every test fails.
struct Sphere {
  enum : std::size_t { x, y, z, r, kCount };
  static constexpr float kPad[kCount] = {0, 0, 0, -kPadInf};
};

// Boxes as centre and half extents, the layout of culling. Padding: extents -inf.
struct Bounds {
  enum : std::size_t { cx, cy, cz, ex, ey, ez, kCount };
  static constexpr float kPad[kCount] = {0, 0, 0, -kPadInf, -kPadInf, -kPadInf};
};

// Triangles as their vertices: field vertex + 3 * v + k is coordinate k (x, y, z) of vertex v
// (a, b, c). Padding: all vertices at the origin, which no ray hits (no area).
struct Triangle {
  enum : std::size_t { vertex = 0, kCount = 9 };
  static constexpr float kPad[kCount] = {};
};

// Oriented boxes: field center + k and half + k are coordinate k of the centre and the half
// extents, axis + 3 * c + k is coordinate k of axis c (axes(k, c) of ObbT). Padding: a point box
// at the origin with identity axes; no value makes a separating-axis test fail, so kernels mask
// lanes >= count instead.
struct Obb {
  enum : std::size_t { center = 0, half = 3, axis = 6, kCount = 15 };
  static constexpr float kPad[kCount] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
};

// Points. Padding: zeros.
struct Point {
  enum : std::size_t { x, y, z, kCount };
  static constexpr float kPad[kCount] = {};
};

// Circles as centre and radius. Padding: radius -inf, which every test fails.
struct Circle {
  enum : std::size_t { x, y, r, kCount };
  static constexpr float kPad[kCount] = {0, 0, -kPadInf};
};

// Axis-aligned rectangles as min/max corners. Padding: empty rectangles (min = +inf,
// max = -inf), which overlap and contain nothing.
struct Rect {
  enum : std::size_t { minX, minY, maxX, maxY, kCount };
  static constexpr float kPad[kCount] = {kPadInf, kPadInf, -kPadInf, -kPadInf};
};

// Oriented rectangles as centre, half extents, the rotation's cosine and sine (local x =
// (cos, sin), local y = (-sin, cos)) and the rotation. Padding: half extents -inf, axes the
// identity; kernels that could make a NaN of it (-inf * 0) mask padded lanes out by the sign of
// the half extent.
struct OrientedRect {
  enum : std::size_t { cx, cy, hx, hy, cos, sin, rotation, kCount };
  static constexpr float kPad[kCount] = {0, 0, -kPadInf, -kPadInf, 1, 0, 0};
};

// Rays: origin + k, direction + k (any non-zero length) and tMax (>= 0). Padding: tMax = -inf,
// which hits nothing.
struct Ray {
  enum : std::size_t { origin = 0, direction = 3, tMax = 6, kCount };
  static constexpr float kPad[kCount] = {0, 0, 0, 0, 0, 1, -kPadInf};
};

// Particles (particles.hpp): position, velocity, inverse mass and the force set on each. Padding:
// inverse mass 0, a pinned particle, which the step neither moves nor collides.
struct Particle {
  enum : std::size_t { x, y, z, vx, vy, vz, invMass, fx, fy, fz, kCount };
  static constexpr float kPad[kCount] = {};
};

// Rigid bodies (rigid.hpp): position, orientation (quaternion x, y, z, w), linear and angular
// velocity, inverse mass and the inverse inertia about the body's own axes, the shape (kind
// 0 sphere, 1 box; ex, ey, ez the box's half extents, ex the sphere's radius), friction,
// restitution, the force and torque held on it, and its sleep: the time it has been still (s)
// and, while asleep, its island's id + 1 (0: awake; exact as a float below 2^24 bodies).
// Padding: zeros, inverse mass 0, which no step moves.
struct Body {
  enum : std::size_t {
    x,
    y,
    z,
    qx,
    qy,
    qz,
    qw,
    vx,
    vy,
    vz,
    wx,
    wy,
    wz,
    invMass,
    invIx,
    invIy,
    invIz,
    shape,
    ex,
    ey,
    ez,
    friction,
    restitution,
    fx,
    fy,
    fz,
    tx,
    ty,
    tz,
    sleepTime,
    island,
    hull,  // a hull body's shape: its index in RigidBodies' hulls, else 0
    kCount
  };
  static constexpr float kPad[kCount] = {};
};

}  // namespace simdphys::fields
