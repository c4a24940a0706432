// Obstacles (obstacles.hpp): the static solids, validated on entry, kept dense behind handles.
#include <string>

#include "simdphys/obstacles.hpp"
#include "src/reference/particles/step-inl.hpp"

namespace simdphys {

Handle Obstacles::add(const ObstacleShape& shape) {
  const std::string where = "Obstacles::add: obstacle " + std::to_string(shapes_.size());
  std::visit([&](const auto& s) { validate(s, where); }, shape);
  shapes_.push_back(shape);
  return handles_.add();
}

void Obstacles::remove(Handle h) {
  const std::uint32_t i = handles_.remove(h, "Obstacles::remove", "obstacle");
  shapes_[i] = shapes_.back();
  shapes_.pop_back();
}

const ObstacleShape& Obstacles::operator[](Handle h) const {
  return shapes_[handles_.index(h, "Obstacles::operator[]", "obstacle")];
}

bool Obstacles::inside(const Vec3f& p) const {
  for (const ObstacleShape& o : shapes_)
    if (std::visit([&](const auto& s) { return reference::exitOf(s, p).has_value(); }, o))
      return true;
  return false;
}

}  // namespace simdphys
