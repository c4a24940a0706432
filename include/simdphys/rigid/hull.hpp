// Convex hull shapes for rigid bodies: the general convex case of the book's appendix, collided
// through GJK and EPA (geometry3d/gjk.hpp, epa.hpp) and the face clipping of box-box
// (rigid/manifold.hpp).
//
// A HullShape is built once from a set of points and shared by every body made of it (Jolt's
// ConvexHullShape, Bullet's btConvexHullShape): its vertices, its faces as polygons (coplanar
// triangles merged, so a box given as 8 points has 6 square faces), and its mass properties for a
// uniform density. The shape is re-expressed about its centre of mass in its principal axes, where
// its inertia is diagonal, as the solver holds every body: a hull body's position is its centre of
// mass and its orientation that frame's. centre() and rotation() say where that frame lies in the
// points' own: a point p of the input is at centre() + rotation() * v in the shape's frame.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "simdphys/math.hpp"

namespace simdphys {

namespace detail {
struct Snapshot;
}

class HullShape {
 public:
  // Limits that keep a contact's feature ids and clipping within fixed sizes (Jolt caps a hull at
  // 256 vertices too).
  static constexpr int kMaxVertices = 256;
  static constexpr int kMaxFaceVertices = 64;
  static constexpr int kMaxPoints = 4096;

  // The hull of `points` (interior and repeated points allowed). Throws Error naming `where` if
  // there are fewer than 4 or more than kMaxPoints points, a point is not finite or out of range,
  // the points are flat (all within about 1e-5 of their extent of one plane), or the hull has more
  // than kMaxVertices vertices or a face of more than kMaxFaceVertices.
  explicit HullShape(std::span<const Vec3f> points, const std::string& where = "HullShape");

  // In the shape's frame (centre of mass at the origin, principal axes).
  std::span<const Vec3f> vertices() const { return vertices_; }
  int faceCount() const { return int(faceStart_.size()) - 1; }
  // Face f's vertex indices, counter-clockwise seen from outside.
  std::span<const std::uint8_t> face(int f) const {
    return std::span<const std::uint8_t>(faceIndices_)
        .subspan(faceStart_[std::size_t(f)],
                 faceStart_[std::size_t(f) + 1] - faceStart_[std::size_t(f)]);
  }
  // Face f's plane: outward unit normal n and offset d, n . x = d on the face.
  const Vec3f& faceNormal(int f) const { return normals_[std::size_t(f)]; }
  float faceOffset(int f) const { return offsets_[std::size_t(f)]; }
  // The largest |coordinate| of a vertex on each axis: a box about the centre holding the shape.
  const Vec3f& halfExtents() const { return half_; }
  float volume() const { return volume_; }
  // The principal moments of inertia per unit mass (m^2): a body of mass m has m * inertia().
  const Vec3f& inertia() const { return inertia_; }
  // The shape's frame in the input points' frame.
  const Vec3f& centre() const { return centre_; }
  const Quatf& rotation() const { return rotation_; }

 private:
  friend struct detail::Snapshot;
  HullShape() = default;

  std::vector<Vec3f> vertices_;
  std::vector<std::uint8_t> faceIndices_;
  std::vector<std::uint32_t> faceStart_;  // faceCount() + 1 offsets into faceIndices_
  std::vector<Vec3f> normals_;
  std::vector<float> offsets_;
  Vec3f half_ = Vec3f::Zero(), inertia_ = Vec3f::Zero(), centre_ = Vec3f::Zero();
  float volume_ = 0;
  Quatf rotation_ = Quatf::Identity();
};

}  // namespace simdphys
