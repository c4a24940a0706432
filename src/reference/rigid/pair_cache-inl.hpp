// Reusing a pair of bodies' manifold from the last step (Jolt's body pair cache): while B's pose
// in A's frame stays within kReuseDistance and 0.1 degree of the pose the manifold was found at,
// its points are carried along with the bodies instead of found again. The points keep their
// ids (so warm starting matches them) and their separations are measured anew, so a pair that
// closes or opens along the normal is still solved at its true depth. A resting stack's pairs
// barely move: their box-box tests, most of a step's narrowphase, are skipped.
#pragma once

#include <cmath>

#include "src/reference/rigid/bodies-inl.hpp"

namespace simdphys::detail {

// How far the pose may move from the one the manifold was found at. Jolt's defaults (1 mm and
// 2 degrees, PhysicsSettings::mBodyPairCache*) let W5's B = 20 pyramid fall here: its points
// drift with the bodies as the boxes creep. Measured on W5 B = 20 (largest displacement at the
// end; afresh every step: 3.8 mm): 1 mm falls, 0.1 mm 8.7 mm, 10 um 5.2 mm at the same speed,
// 1 um reuses nothing (a resting pyramid's pairs move a few um a step).
inline constexpr double kReuseDistance = 1e-5;
inline constexpr double kReuseSinHalfAngle = 8.726645152351496e-4;  // sin(0.1 degree / 2)

template <class T>
struct RelativePose {
  Vec3<T> position;
  Quat<T> rotation;
};

// Ra, Rb: the bodies' orientations as matrices, made once a step for all of a body's pairs
// (rotating by a matrix is half the work of rotating by the quaternion).
template <class T>
RelativePose<T> relativePose(const BodyT<T>& a, const Mat3<T>& Ra, const BodyT<T>& b) {
  return {Ra.transpose() * (b.x - a.x), a.q.conjugate() * b.q};
}

// The manifold m of bodies a and b (the pair `key`) as found now, for reuse in later steps.
template <class T>
PairGeometryT<T> pairGeometry(std::uint64_t key, const ManifoldT<T>& m, const BodyT<T>& a,
                              const Mat3<T>& Ra, const BodyT<T>& b, const Mat3<T>& Rb) {
  PairGeometryT<T> g{};
  g.key = key, g.count = m.count;
  const RelativePose<T> pose = relativePose(a, Ra, b);
  const auto toA = Ra.transpose(), toB = Rb.transpose();
  const Vec3<T> n = toA * m.normal;
  for (int k = 0; k < 3; ++k) g.position[k] = pose.position[k], g.normal[k] = n[k];
  for (int k = 0; k < 4; ++k) g.rotation[k] = pose.rotation.coeffs()[k];
  for (int i = 0; i < m.count; ++i) {
    const ContactPointT<T>& p = m.points[std::size_t(i)];
    const Vec3<T> half = p.separation / 2 * m.normal;
    const Vec3<T> onA = toA * Vec3<T>(p.point - half - a.x),
                  onB = toB * Vec3<T>(p.point + half - b.x);
    for (int k = 0; k < 3; ++k) g.onA[i][k] = onA[k], g.onB[i][k] = onB[k];
    g.id[i] = p.id;
  }
  return g;
}

// Whether the pair's pose is still near the one its cached manifold was found at.
template <class T>
bool reusable(const PairGeometryT<T>& g, const BodyT<T>& a, const Mat3<T>& Ra, const BodyT<T>& b) {
  const RelativePose<T> pose = relativePose(a, Ra, b);
  const Vec3<T> moved = pose.position - Vec3<T>(g.position[0], g.position[1], g.position[2]);
  const Quat<T> was(g.rotation[3], g.rotation[0], g.rotation[1], g.rotation[2]);
  // The turn between the two: its vector part is sin(angle / 2) along the axis.
  const T turn = (was.conjugate() * pose.rotation).vec().squaredNorm();
  return moved.squaredNorm() <= T(kReuseDistance * kReuseDistance) &&
         turn <= T(kReuseSinHalfAngle * kReuseSinHalfAngle);
}

// The cached manifold g carried to the bodies' poses now: the surface points moved with their
// bodies, the normal with A, each separation measured between the two points along it.
template <class T>
ManifoldT<T> reused(const PairGeometryT<T>& g, const BodyT<T>& a, const Mat3<T>& Ra,
                    const BodyT<T>& b, const Mat3<T>& Rb) {
  ManifoldT<T> m;
  m.normal = Ra * Vec3<T>(g.normal[0], g.normal[1], g.normal[2]);
  m.count = g.count;
  for (int i = 0; i < m.count; ++i) {
    const Vec3<T> onA = a.x + Ra * Vec3<T>(g.onA[i][0], g.onA[i][1], g.onA[i][2]);
    const Vec3<T> onB = b.x + Rb * Vec3<T>(g.onB[i][0], g.onB[i][1], g.onB[i][2]);
    ContactPointT<T>& p = m.points[std::size_t(i)];
    p.separation = (onB - onA).dot(m.normal);
    p.point = onA + p.separation / 2 * m.normal;
    p.id = g.id[i];
  }
  return m;
}

}  // namespace simdphys::detail
