// Prints the active path, or the error SIMDPHYS_ISA causes (for the tests in CMakeLists.txt).
#include <cstdio>

#include "simdphys/core.hpp"

int main() {
  try {
    std::printf("active path: %s\n", simdphys::activePath().c_str());
  } catch (const simdphys::Error& e) {
    std::printf("error: %s\n", e.what());
    return 1;
  }
}
