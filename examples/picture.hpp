// What the picture examples (cloth, pyramid) share: one primary ray a pixel through a scene, the
// sky where a ray hits nothing, and the PNG (stb_image_write, from Debian's libstb-dev). Included
// by one file of each example (it holds stb's implementation).
#pragma once

#include <simdphys/scene/scene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace picture {

inline std::uint8_t toByte(float v) {
  return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255));
}

// Casts the camera's rays (width x height) through the scene and writes the PNG: shade(hit, ray)
// where a ray hits, the sky, lighter towards the horizon, where it does not. False, after saying
// so on stderr, if the file cannot be written.
template <class Shade>
bool write(const std::string& path, const simdphys::Scene& scene, const simdphys::Camera& camera,
           int width, int height, Shade&& shade) {
  using simdphys::Vec3f;
  const simdphys::RayStream rays = camera.primaryRays();
  std::vector<simdphys::ModelHit> hits(rays.size());
  scene.raycast(rays, hits);
  std::vector<std::uint8_t> image(rays.size() * 3);
  for (std::size_t p = 0; p < hits.size(); ++p) {
    const simdphys::Ray ray = rays[p];
    const Vec3f colour = hits[p].hit()
                             ? Vec3f(shade(hits[p], ray))
                             : Vec3f(Vec3f(0.75f, 0.82f, 0.92f) -
                                     0.3f * std::abs(ray.direction.y()) * Vec3f(0.4f, 0.3f, 0.1f));
    for (int c = 0; c < 3; ++c) image[3 * p + std::size_t(c)] = toByte(colour[c]);
  }
  if (stbi_write_png(path.c_str(), width, height, 3, image.data(), width * 3)) return true;
  std::fprintf(stderr, "error: cannot write %s\n", path.c_str());
  return false;
}

}  // namespace picture
