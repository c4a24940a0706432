// Batch forms of the 3D queries: one shape or ray against a whole stream, a SIMD vector of
// elements at a time. Each answers exactly as its scalar function does for every element
// (intersect.hpp, point_tests.hpp, raycast.hpp), on every path.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/geometry3d/streams.hpp"

namespace simdphys {

// Every query validates its argument (validate() of primitives.hpp: within the supported range of
// math.hpp) and throws Error naming the function and field, e.g. "overlapping: radius is -1, ...".

// The indices (ascending) of the spheres / boxes that `sphere` intersects (closed), written to
// `out`; returns their number.
std::size_t overlapping(const Sphere& sphere, const SphereStream& spheres,
                        std::vector<std::uint32_t>& out);
std::size_t overlapping(const Sphere& sphere, const BoxStream& boxes,
                        std::vector<std::uint32_t>& out);
// The indices (ascending) of the oriented boxes that `box` intersects (closed): intersects(box,
// boxes[i]) of intersect.hpp, bit for bit. Throws Error if `box` is invalid (validate(Obb)).
std::size_t overlapping(const Obb& box, const ObbStream& boxes, std::vector<std::uint32_t>& out);
// The indices (ascending) of the boxes that contain `point` (closed).
std::size_t containing(const Vec3f& point, const BoxStream& boxes, std::vector<std::uint32_t>& out);
// For every box, the point of it closest to `point` (the point itself when inside).
void closestPoints(const Vec3f& point, const BoxStream& boxes, PointStream& out);

// The first element a ray hits (core.hpp's ElementHit: its index and t; a miss is index kNoHit):
// the smallest t in [0, tMax] by raycast()'s rules (a ray that starts inside a solid hits where
// it leaves), ties to the smaller index. Throws Error if the ray is invalid (validate(Ray)) or
// tMax is negative or NaN (+inf is the default: no limit).
ElementHit raycast(const Ray& ray, const BoxStream& boxes,
                   float tMax = std::numeric_limits<float>::infinity());
ElementHit raycast(const Ray& ray, const SphereStream& spheres,
                   float tMax = std::numeric_limits<float>::infinity());
// Watertight (Woop, Benthin and Wald 2013), two-sided.
ElementHit raycast(const Ray& ray, const TriangleStream& triangles,
                   float tMax = std::numeric_limits<float>::infinity());

}  // namespace simdphys
