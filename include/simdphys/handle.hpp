// Generational handles: how a container that keeps its elements dense (removal moves the last
// element into the hole) names an element for as long as it lives. A handle is a slot, which
// keeps pointing at its element wherever the element moves, and the slot's generation, bumped when
// the element is removed: a handle kept past its element's removal is stale even after the slot
// is reused, and the container rejects it with an Error rather than answering for another element.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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

// The slots of a dense container: handle -> index and index -> handle. The container adds its
// element at index size() with add(), and on remove() moves its last element into the index
// remove() returns, as the table does with the handles.
class HandleTable {
 public:
  std::size_t size() const { return slotOf_.size(); }
  std::size_t slots() const { return slots_.size(); }
  bool contains(Handle h) const {
    return h.slot < slots_.size() && slots_[h.slot].generation == h.generation && h.generation != 0;
  }
  // The index of h's element. Throws Error naming `where`, the element kind `what` ("particle")
  // and the handle if h is out of range or stale.
  std::uint32_t index(Handle h, const char* where, const char* what) const;
  Handle handle(std::uint32_t index) const {
    return {slotOf_[index], slots_[slotOf_[index]].generation};
  }
  Handle add();
  // Frees h's slot (its generation moves on) and returns the index whose element the container
  // must overwrite with its last one before dropping the last. Throws as index() does.
  std::uint32_t remove(Handle h, const char* where, const char* what);
  void clear() { *this = HandleTable(); }

 private:
  friend struct detail::Snapshot;
  struct Slot {
    std::uint32_t index, generation;
  };
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> slotOf_;  // index -> slot
  std::vector<std::uint32_t> free_;
};

}  // namespace simdphys
