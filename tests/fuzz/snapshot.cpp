// Fuzz target: bytes through restore(). A damaged snapshot must be an Error; one it restores must
// snapshot again to the same bytes and step.
#include <cstring>
#include <span>

#include "simdphys/snapshot.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simdphys;
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  World world;
  try {
    world = restore(bytes);
  } catch (const Error&) {
    return 0;
  }
  const std::vector<std::byte> again = snapshot(world);
  fuzz::require(again.size() == size && std::memcmp(again.data(), data, size) == 0,
                "a restored world does not snapshot to the bytes it came from");
  try {
    world.step();
  } catch (const Error&) {
  }
  return 0;
}
