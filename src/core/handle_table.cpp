// HandleTable (handle.hpp): the slots behind the generational handles of every dense container.
#include <string>

#include "simdphys/core.hpp"
#include "simdphys/handle.hpp"

namespace simdphys {

std::uint32_t HandleTable::index(Handle h, const char* where, const char* what) const {
  if (h.slot >= slots_.size())
    throw Error(std::string(where) + ": " + what + " " + std::to_string(h.slot) +
                " is out of range (" + std::to_string(slots_.size()) + " slots; handle " +
                toString(h) + ")");
  const Slot& s = slots_[h.slot];
  if (s.generation != h.generation || h.generation == 0)
    throw Error(std::string(where) + ": the handle (" + toString(h) + ") is stale: its " + what +
                " was removed (the slot is at generation " + std::to_string(s.generation) + ")");
  return s.index;
}

Handle HandleTable::add() {
  const auto i = std::uint32_t(slotOf_.size());
  std::uint32_t slot;
  if (free_.empty()) {
    slot = std::uint32_t(slots_.size());
    slots_.push_back({i, 1});
  } else {
    slot = free_.back();
    free_.pop_back();
    slots_[slot].index = i;
  }
  slotOf_.push_back(slot);
  return {slot, slots_[slot].generation};
}

std::uint32_t HandleTable::remove(Handle h, const char* where, const char* what) {
  const std::uint32_t i = index(h, where, what);
  slotOf_[i] = slotOf_.back();
  slots_[slotOf_[i]].index = i;
  slotOf_.pop_back();
  Slot& freed = slots_[h.slot];
  freed.index = ~0u;
  if (++freed.generation == 0) freed.generation = 1;  // 0 is never live
  free_.push_back(h.slot);
  return i;
}

}  // namespace simdphys
