// Fuzz target: scene-file text through parseScene. Malformed text must be an Error naming the
// place; a scene it builds must step (a small one is stepped once) and stay finite.
#include <string_view>

#include "simdphys/measures.hpp"
#include "simdphys/scene_file.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simdphys;
  SceneFile scene;
  try {
    scene = parseScene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const Error& e) {
    fuzz::require(std::string_view(e.what()).starts_with("fuzz: "),
                  std::string("an error that does not name the file: ") + e.what());
    return 0;
  }
  std::size_t elements = scene.world.bodies().size();
  for (std::size_t s = 0; s < scene.world.particleSystemCount(); ++s)
    elements += scene.world.particles(scene.world.particleSystemHandle(s)).size();
  for (std::size_t c = 0; c < scene.world.clothCount(); ++c)
    elements += scene.world.cloth(scene.world.clothHandle(c)).size();
  if (elements > 20'000) return 0;  // a valid scene too large to step at fuzzing speed
  try {
    scene.world.step();
  } catch (const Error&) {
    return 0;  // a step may refuse a state (a body sent out of range): an error, not a crash
  }
  return 0;
}
