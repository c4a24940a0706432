#include <cstdlib>
#include <mutex>

#include "../../simd/kernels.hpp"
#include "simdphys/core.hpp"
#include "src/core/on_path.hpp"

namespace simdphys {
namespace {

constexpr const char* kReference = "reference";

struct PathState {
  std::vector<std::string> paths;
  std::string active;
  bool reference = false;  // active == kReference, asked on every batch query
  std::string error;       // set when SIMDPHYS_ISA names a path this machine lacks
};

PathState& state() {
  static PathState s = [] {
    PathState init;
    init.paths = simd::supportedTargets();
    init.paths.emplace_back(kReference);
    init.active = init.paths.front();
    return init;
  }();
  return s;
}

void activate(PathState& s, std::string_view name) {
  bool known = false;
  for (const std::string& p : s.paths) known |= p == name;
  if (!known) {
    std::string list;
    for (const std::string& p : s.paths) list += (list.empty() ? "" : ", ") + p;
    throw Error("simdphys path '" + std::string(name) +
                "' is unknown or not supported by this CPU (available: " + list + ")");
  }
  if (name != kReference) simd::selectTarget(std::string(name));
  s.active = std::string(name);
  s.reference = name == kReference;
}

// SIMDPHYS_ISA is honoured on first use. A bad value is an error on every use until a path is
// set explicitly: never a silent fallback to another path.
PathState& initialised() {
  static std::once_flag once;
  PathState& s = state();
  std::call_once(once, [&] {
    const char* env = std::getenv("SIMDPHYS_ISA");
    if (!env || !*env) return activate(s, s.active);
    try {
      activate(s, env);
    } catch (const Error& e) {
      s.error = std::string("SIMDPHYS_ISA: ") + e.what();
    }
  });
  if (!s.error.empty()) throw Error(s.error);
  return s;
}

}  // namespace

std::vector<std::string> availablePaths() { return state().paths; }
std::string activePath() { return initialised().active; }
bool referencePathActive() { return initialised().reference; }

void setPath(std::string_view name) {
  PathState& s = state();
  try {
    initialised();
  } catch (const Error&) {
    // An explicit choice replaces a bad SIMDPHYS_ISA.
  }
  activate(s, name);
  s.error.clear();
}

namespace {
bool plainLoops = false;
}  // namespace

bool detail::plainLoopsActive() { return plainLoops; }
void detail::setPlainLoops(bool on) { plainLoops = on; }

}  // namespace simdphys
