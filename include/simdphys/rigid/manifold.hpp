// Contact manifolds (book chapter 15, the appendix's arbiters): where two convex shapes touch or
// are about to, as the rigid-body solver (rigid.hpp) consumes them. A manifold has one normal and
// at most four points; each point carries a feature id that names the pair of features (faces,
// edges, vertices) it comes from, so the solver matches it with last frame's point and warm
// starts it (Box2D's b2ManifoldPoint::id, Jolt's sub-shape ids).
//
// Speculative contacts: a collide() reports points whose separation is at most maxSeparation
// (>= 0), not only penetrating ones, so the solver can stop bodies before they meet (Box2D v3's
// speculative distance; Catto, "Speculative contacts", 2011).
//
// Conventions for a pair (A, B):
//  - normal: unit, from A towards B; moving B along it separates them.
//  - separation: signed distance between the surfaces along the normal at the point (< 0:
//    penetrating by -separation).
//  - point: midway between the two surfaces at the contact (A's surface point +
//    separation / 2 * normal).
// A box-box manifold is found by the separating axis test over the 15 axes (the face normals of
// both boxes and the cross products of their edges) with the axis of least penetration chosen,
// faces preferred over edges within a tolerance (so resting stacks do not flicker between axes);
// face contacts clip the incident face against the reference face's side planes and keep at most
// four points (the deepest, and those spanning the largest area); edge contacts give one point,
// midway between the edges' closest points (when those lie between the edges' ends; otherwise a
// vertex is nearer and the best face axis is used). Near-parallel edge pairs (sine of their angle
// below sqrt(eps)) give no axis. A speculative face contact may miss apart boxes whose closest
// features are two vertices or a vertex and an edge, where the SAT only bounds the distance.
#pragma once

#include <array>
#include <cstdint>

#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/rigid/hull.hpp"

namespace simdphys {

template <class T>
struct ContactPointT {
  Vec3<T> point = Vec3<T>::Zero();
  T separation = 0;
  std::uint32_t id = 0;  // feature pair; unique within a manifold
};

template <class T>
struct ManifoldT {
  static constexpr int kMaxPoints = 4;
  Vec3<T> normal = Vec3<T>::UnitY();
  int count = 0;
  std::array<ContactPointT<T>, kMaxPoints> points{};
};

// Box-box: of two axes of nearly equal separation, B's face is taken over A's, and an edge over
// the faces, only when its separation is larger by kBoxAxisRelativeTolerance |separation| +
// kBoxAxisAbsoluteTolerance (the smaller box's largest half extent), so that a resting stack keeps
// its axis (and its points' ids) from frame to frame (box2d-lite's and qu3e's 0.95 and 0.01). The
// manifold's depth may then exceed the least penetration by up to that much.
template <class T>
inline constexpr T kBoxAxisRelativeTolerance = T(0.05);
template <class T>
inline constexpr T kBoxAxisAbsoluteTolerance = T(1e-3);

// Box-box face contacts: a corner of the incident face within kBoxClipSnap (times the smaller
// box's largest half extent) outside a side plane of the reference face is kept as it is, rather
// than clipped into two nearly coincident points, so that flush faces (a stack of equal boxes)
// keep their points and ids through rounding; such a point lies up to that far outside the face.
template <class T>
inline constexpr T kBoxClipSnap = T(1e-4);

using ContactPoint = ContactPointT<float>;
using Manifold = ManifoldT<float>;
using Manifoldd = ManifoldT<double>;

// The manifold of each pair of shapes the rigid bodies need (bodies are spheres, boxes and hulls;
// static obstacles add planes and the triangles of meshes). Compiled for float and double
// (src/reference/rigid/manifold.cpp).
template <class T>
ManifoldT<T> collide(const SphereT<T>& a, const SphereT<T>& b, T maxSeparation);
template <class T>
ManifoldT<T> collide(const SphereT<T>& a, const ObbT<T>& b, T maxSeparation);
template <class T>
ManifoldT<T> collide(const ObbT<T>& a, const ObbT<T>& b, T maxSeparation);
template <class T>
ManifoldT<T> collide(const SphereT<T>& a, const PlaneT<T>& b, T maxSeparation);
template <class T>
ManifoldT<T> collide(const ObbT<T>& a, const PlaneT<T>& b, T maxSeparation);

// Against one triangle of a mesh, a two-sided surface: the normal points from the shape to the
// triangle on whichever side the shape is. Sphere: its centre's closest point on the triangle.
// Box: the separating axis test over 13 axes (the triangle's normal, the box's 3 face normals, the
// 9 cross products of their edges), the triangle's face preferred within the tolerances of
// box-box, then a face contact (the box's face clipped against the triangle's edges, or the
// triangle against the box's face) or an edge contact. `activeEdges` (bits 0-2, mesh.hpp's
// activeEdges): only an active edge of the triangle gives an edge axis, and a box's face axis is
// taken only where the triangle's features nearest it (an edge, or a vertex and its two edges)
// include an active edge; otherwise the triangle's face axis is, so a box crossing flat ground
// made of many triangles never catches on the edges between them (Jolt's active edges). Point ids
// stay below 1024 (room for the triangle's id above them).
template <class T>
ManifoldT<T> collide(const SphereT<T>& a, const TriangleT<T>& b, T maxSeparation);
template <class T>
ManifoldT<T> collide(const ObbT<T>& a, const TriangleT<T>& b, T maxSeparation,
                     unsigned activeEdges = 7);

// A hull shape placed in the world: its frame (rigid/hull.hpp) at `center` with `axes`.
template <class T>
struct PlacedHullT {
  const HullShape* shape;
  Vec3<T> center;
  Mat3<T> axes;
};

// Hulls, the general convex case (src/reference/rigid/hull-inl.hpp): GJK finds the nearest
// features of shapes apart within maxSeparation, EPA of overlapping ones; then the separating
// axis test over both shapes' faces (a hull's, a box's, the triangle's two sides), with box-box's
// rule and tolerances: B's face over A's, and either over the edge contact GJK or EPA found, only
// when clearly better. The other shape's face most against the chosen one is clipped against its
// sides as box-box clips, duplicates kept once, the points within maxSeparation kept, at most
// four as box-box keeps them. An edge or vertex contact is GJK's or EPA's single point; apart
// shapes whose face clips to nothing have no contact (as box-box has none there). Against a
// triangle, an inactive edge never gives the normal (as for boxes): the triangle's face does,
// with the hull's deepest vertex along it. Against a plane: the vertices within maxSeparation,
// four kept. Ids name the two faces and the clipped polygon's edges (below 1024 against a
// triangle).
template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const SphereT<T>& b, T maxSeparation);
template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const ObbT<T>& b, T maxSeparation);
template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const PlacedHullT<T>& b, T maxSeparation);
template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const PlaneT<T>& b, T maxSeparation);
template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const TriangleT<T>& b, T maxSeparation,
                     unsigned activeEdges = 7);

// The same manifold seen from the other shape: the normal reversed, points and ids kept.
template <class T>
ManifoldT<T> flipped(ManifoldT<T> m) {
  m.normal = -m.normal;
  return m;
}

}  // namespace simdphys
