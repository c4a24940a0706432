// The sections of a scene file (docs/scenes.md), each read from its node into the world being
// built, its handles recorded in the scene.
#pragma once

#include <filesystem>

#include "json_node.hpp"
#include "simdphys/scene_file.hpp"

namespace simdphys::scenefile {

// Sizes a file may ask for: large enough for any real scene, small enough that a typo (a count of
// 1e12) is an error rather than an attempt to allocate terabytes.
inline constexpr std::int64_t kMaxElements = 100'000'000;

ObstacleShape obstacle(const Node& n, const std::filesystem::path& folder);
void particleSystem(const Node& n, World& world, SceneFile& scene);
void cloth(const Node& n, World& world, SceneFile& scene);
void rigid(const Node& n, World& world, SceneFile& scene);

// Runs `build`; an Error from the library (which names its own function and element) is reported
// at n's place in the file.
template <class F>
auto within(const Node& n, F&& build) {
  try {
    return build();
  } catch (const Error& e) {
    if (std::string_view(e.what()).starts_with(n.file() + ": ")) throw;  // placed already
    n.fail(e.what());
  }
}

}  // namespace simdphys::scenefile
