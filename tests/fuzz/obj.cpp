// Fuzz target: OBJ text through parseObj (loadObj's parser). Malformed text must be an Error; a
// mesh it returns must keep parseObj's promises.
#include <cmath>
#include <string_view>

#include "simdphys/mesh.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simdphys;
  Mesh m;
  try {
    m = parseObj(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const Error&) {
    return 0;
  }
  fuzz::require(!m.triangles.empty(), "parseObj returned a mesh without triangles");
  for (const Vec3f& v : m.vertices)
    fuzz::require(v.allFinite() && v.cwiseAbs().maxCoeff() <= kMaxCoordinate,
                  "parseObj returned a vertex outside the supported range");
  try {
    m.validate("fuzz");
  } catch (const Error& e) {
    fuzz::finding(std::string("parseObj returned a mesh that validate() rejects: ") + e.what());
  }
  return 0;
}
