// Scene files: a World described in JSON (docs/scenes.md, field by field): the world's settings,
// static obstacles (planes, spheres, boxes, OBJ meshes), particle systems and their emitters,
// cloths (grids or spring networks) and rigid bodies (one by one or as pyramids), and how long a
// run of it lasts. scenes/ holds the standard workloads W3, W4 and W5 as scene files.
//
// Loading is all or nothing: the first problem found throws Error naming the file, the JSON
// pointer of the value (RFC 6901) and what is wrong, e.g.
//   pyramid.json: /rigid/bodies/17/halfExtents/1: must be positive, got -0.5
// and nothing is built then.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "simdphys/world.hpp"

namespace simdphys {

// The scene-file format this library writes and reads ("simdphys": 1 in the file).
inline constexpr int kSceneFormatVersion = 1;
// Larger files are refused before they are read.
inline constexpr std::uintmax_t kMaxSceneFileBytes = 256u << 20;

// Where a picture of the scene is taken from (simdphys render), if the file says.
struct SceneCamera {
  bool given = false;
  Vec3f eye{10, 6, 14}, target{0, 0, 0};
  float fovDegrees = 45;  // vertical, in (0, 180)
};

struct SceneFile {
  std::string name, description;
  SceneCamera camera;
  int frames = 60;            // world steps a run of the scene takes
  std::string path = "auto";  // the execution path it asks for ("auto": the best this CPU has)
  World world;
  // What the file made, in its order.
  std::vector<Handle> obstacles, particleSystems, cloths, bodies;
};

// A change to a scene's JSON before it is read, as a parameter sweep varies a scene: the value at
// `pointer` (RFC 6901, e.g. "/rigid/settings/substeps") replaced by, or, in an existing object,
// added as, the JSON text `json` (e.g. "4").
struct ScenePatch {
  std::string pointer, json;
};

// Reads the scene in `file`, patched; OBJ meshes are found relative to the file's folder.
SceneFile loadScene(const std::filesystem::path& file, std::span<const ScenePatch> patches = {});
// The same from JSON text: `name` stands for the file in errors, meshes are found in `folder`.
SceneFile parseScene(std::string_view text, const std::string& name,
                     const std::filesystem::path& folder = {},
                     std::span<const ScenePatch> patches = {});

}  // namespace simdphys
