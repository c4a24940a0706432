// Scene files (scene_file.hpp): the file, its JSON and patches, and the top level; the sections
// (sections.cpp) are read into a World that is handed out only when the whole file has been read.
#include "simdphys/scene_file.hpp"

#include <fstream>
#include <memory>
#include <sstream>

#include "sections.hpp"
#include "settings.hpp"

namespace simdphys {
namespace scenefile {
namespace {

constexpr std::int64_t kMaxFrames = 100'000'000;

Json parseJson(std::string_view text, const std::string& name) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw Error(name + ": the file is empty (a scene file is a JSON object)");
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line 3, column 12: ..."
    const std::string what = e.what();
    const auto at = what.find("parse error");
    throw Error(name + ": not valid JSON: " + (at == std::string::npos ? what : what.substr(at)));
  }
}

// The patches applied in order: each value replaces (or adds, in an existing object) the one at
// its pointer.
void patch(Json& json, std::span<const ScenePatch> patches, const std::string& name) {
  for (const ScenePatch& p : patches) {
    const std::string where = name + ": patch " + p.pointer;
    try {
      const Json::json_pointer pointer(p.pointer);
      if (!pointer.empty() && !json.contains(pointer.parent_pointer()))
        throw Error(where + ": no such place in the scene");
      json[pointer] = parseJson(p.json, where);
    } catch (const Json::exception& e) {
      throw Error(where + ": " + e.what());
    }
  }
}

SceneFile build(const Json& json, const std::string& name, const std::filesystem::path& folder);

}  // namespace
}  // namespace scenefile

SceneFile parseScene(std::string_view text, const std::string& name,
                     const std::filesystem::path& folder, std::span<const ScenePatch> patches) {
  scenefile::Json json = scenefile::parseJson(text, name);
  scenefile::patch(json, patches, name);
  return scenefile::build(json, name, folder);
}

namespace scenefile {
namespace {
SceneFile build(const Json& json, const std::string& name, const std::filesystem::path& folder) {
  const Node root(json, "", name);
  root.keys({"simdphys", "name", "description", "settings", "camera", "obstacles", "particles",
             "cloths", "rigid"});
  const Node version = root.require("simdphys");
  if (version.integer(0, INT32_MAX) != kSceneFormatVersion)
    version.fail("format version " + version.json().dump() + " is not one this library reads (" +
                 std::to_string(kSceneFormatVersion) + ")");
  SceneFile scene;
  if (auto n = root.find("name")) scene.name = n->string();
  if (auto n = root.find("description")) scene.description = n->string();
  WorldSettings settings;
  if (auto s = root.find("settings")) {
    s->keys({"timeStep", "substeps", "threads", "frames", "path"});
    settings = worldSettings(*s);
    if (auto f = s->find("frames")) scene.frames = int(f->integer(0, kMaxFrames));
    if (auto p = s->find("path")) scene.path = p->string();
  }
  if (auto c = root.find("camera")) {
    c->keys({"eye", "target", "fov"});
    scene.camera.given = true;
    scene.camera.eye = c->require("eye").vec3();
    scene.camera.target = c->require("target").vec3();
    c->read("fov", scene.camera.fovDegrees, 1, 179);
    if ((scene.camera.eye - scene.camera.target).norm() == 0)
      c->require("target").fail("must differ from eye");
  }
  World world(settings);
  if (auto list = root.find("obstacles"))
    for (std::size_t i = 0, count = list->size(kMaxElements); i < count; ++i)
      scene.obstacles.push_back(
          within((*list)[i], [&] { return world.obstacles().add(obstacle((*list)[i], folder)); }));
  if (auto list = root.find("particles"))
    for (std::size_t i = 0, count = list->size(10'000); i < count; ++i)
      particleSystem((*list)[i], world, scene);
  if (auto list = root.find("cloths"))
    for (std::size_t i = 0, count = list->size(10'000); i < count; ++i)
      cloth((*list)[i], world, scene);
  if (auto r = root.find("rigid")) rigid(*r, world, scene);
  scene.world = std::move(world);
  return scene;
}
}  // namespace
}  // namespace scenefile

SceneFile loadScene(const std::filesystem::path& file, std::span<const ScenePatch> patches) {
  const std::string name = file.string();
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw Error(name + ": is a directory, not a scene file");
  const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
  if (ec) throw Error(name + ": cannot be read (" + ec.message() + ")");
  if (bytes > kMaxSceneFileBytes)
    throw Error(name + ": the file is " + std::to_string(bytes >> 20) + " MiB, more than the " +
                std::to_string(kMaxSceneFileBytes >> 20) + " MiB a scene file may be");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  if (!(in && text << in.rdbuf()) && bytes > 0) throw Error(name + ": cannot be read");
  return parseScene(text.str(), name, file.parent_path(), patches);
}

}  // namespace simdphys
