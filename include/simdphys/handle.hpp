// Generational handles: how a container that keeps its elements dense (removal moves the last
// element into the hole) names an element for as long as it lives. A handle is a slot, which
// keeps pointing at its element wherever the element moves, and the slot's generation, bumped when
// the element is removed: a handle kept past its element's removal is stale even after the slot
// is reused, and the container rejects it with an Error rather than answering for another element.
#pragma once

#include <cstdint>
#include <string>

namespace simdphys {

struct Handle {
  std::uint32_t slot = ~0u;
  // Live generations start at 1: the default handle names nothing.
  std::uint32_t generation = 0;
  friend bool operator==(const Handle&, const Handle&) = default;
};

// The handle as text for messages: "slot 3, generation 2".
inline std::string toString(const Handle& h) {
  return "slot " + std::to_string(h.slot) + ", generation " + std::to_string(h.generation);
}

}  // namespace simdphys
