#include "workloads.hpp"

#include <cmath>
#include <numbers>

#include "simdphys/geometry2d/collisions.hpp"

namespace simdphys::workloads {

namespace {
Aabb randomBox(Random& r, float halfMin, float halfMax) {
  Vec3f c, h;
  for (int a = 0; a < 3; ++a) c[a] = r.uniform(-100, 100);
  for (int a = 0; a < 3; ++a) h[a] = r.uniform(halfMin, halfMax);
  return {c - h, c + h};
}
}  // namespace

AabbWorkload makeAabbWorkload(std::size_t boxes, std::size_t queries) {
  Random r(1);
  AabbWorkload w;
  w.boxes.reserve(boxes);
  for (std::size_t i = 0; i < boxes; ++i) w.boxes.push(randomBox(r, 0.1f, 1.5f));
  for (std::size_t q = 0; q < queries; ++q) w.queries.push_back(randomBox(r, 1, 8));
  return w;
}

std::uint64_t pairChecksum(std::span<const Pair> pairs, std::size_t n) {
  std::uint64_t sum = 0;
  for (const Pair& p : pairs) sum += std::uint64_t(p.a) * n + p.b;
  return sum;
}

CullWorkload makeCullWorkload(std::size_t n) {
  Random r(6);
  CullWorkload w;
  w.spheres.reserve(n);
  w.boxes.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    Vec3f c;
    for (int a = 0; a < 3; ++a) c[a] = r.uniform(-500, 500);
    float radius = r.uniform(0.5f, 5);
    w.spheres.push({c, radius});
    w.boxes.push(c, Vec3f::Constant(radius));
  }
  Mat4d view = lookAt(Vec3d(0, 0, 0), Vec3d(0, 0, 1), Vec3d(0, 1, 0));
  Mat4d proj = perspective(std::numbers::pi / 3, 16.0 / 9.0, 0.1, 1000.0);
  w.viewProjection = proj * view;
  w.frustum = Frustumd::fromMatrix(w.viewProjection).cast<float>();
  return w;
}

namespace {
// One W7 shape, in draw order: centre x and y, then the circle's radius (even i) or the
// rectangle's half extents x and y and its rotation (odd i).
struct Shape2d {
  Circle circle;
  OrientedRect rect;
};
Shape2d drawShape2d(Random& r, std::size_t i, float half) {
  const float pi = float(std::numbers::pi);
  Shape2d s{};
  const float x = r.uniform(-half, half);
  const float y = r.uniform(-half, half);
  if (i % 2 == 0) {
    s.circle = {{x, y}, r.uniform(0.5f, 2.5f)};
    return s;
  }
  const float hx = r.uniform(0.5f, 2.5f);
  const float hy = r.uniform(0.5f, 2.5f);
  s.rect = {{x, y}, {hx, hy}, r.uniform(-pi, pi)};
  return s;
}
}  // namespace

Shapes2dWorkload makeShapes2dWorkload(std::size_t shapes, std::size_t queries) {
  Random r(7);
  // Half the side of the square: 40 square units per shape at every N.
  const float half = float(std::sqrt(10.0 * double(shapes)));
  Shapes2dWorkload w;
  w.circles.reserve(shapes / 2 + 1);
  w.orientedRects.reserve(shapes / 2 + 1);
  w.bounds.reserve(shapes);
  for (std::size_t i = 0; i < shapes; ++i) {
    const Shape2d s = drawShape2d(r, i, half);
    if (i % 2 == 0) {
      w.circles.push(s.circle);
      w.bounds.push(boundingRect(s.circle));
    } else {
      w.orientedRects.push(s.rect);
      w.bounds.push(boundingRect(s.rect));
    }
  }
  for (std::size_t q = 0; q < queries; ++q) {
    const Shape2d s = drawShape2d(r, q, half);
    if (q % 2 == 0)
      w.queryCircles.push_back(s.circle);
    else
      w.queryOrientedRects.push_back(s.rect);
  }
  return w;
}

const Shapes2dReference& shapes2dReference(std::size_t shapes) {
  static constexpr Shapes2dReference kFigures[] = {
      {100, 67, 51},
      {300, 158, 119},
      {1'000, 605, 427},
      {3'000, 1'873, 1'366},
      {10'000, 6'040, 4'444},
      {30'000, 18'052, 12'912},
      {100'000, 61'074, 43'894},
  };
  for (const Shapes2dReference& f : kFigures)
    if (f.shapes == shapes) return f;
  throw Error("no W7 reference figures for N = " + std::to_string(shapes));
}

std::uint64_t collidingPairs(const Shapes2dWorkload& w, std::span<const Pair> candidates) {
  std::uint64_t count = 0;
  for (const Pair& p : candidates) {
    const bool aCircle = p.a % 2 == 0, bCircle = p.b % 2 == 0;
    const std::size_t a = p.a / 2, b = p.b / 2;
    if (aCircle && bCircle)
      count += intersects(w.circles[a], w.circles[b]);
    else if (aCircle)
      count += intersects(w.circles[a], w.orientedRects[b]);
    else if (bCircle)
      count += intersects(w.orientedRects[a], w.circles[b]);
    else
      count += intersects(w.orientedRects[a], w.orientedRects[b]);
  }
  return count;
}

}  // namespace simdphys::workloads
