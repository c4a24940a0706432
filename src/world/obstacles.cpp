// Obstacles (obstacles.hpp): the static shapes, validated on entry, kept dense behind handles,
// and the tree over their bounds when there are many.
#include <string>

#include "simdphys/obstacles.hpp"
#include "src/reference/particles/step-inl.hpp"
#include "src/world/obstacle_rows.hpp"

namespace simdphys {

namespace {

void validateShape(const ObstacleShape& shape, const std::string& where) {
  if (const auto* mesh = std::get_if<MeshObstacle>(&shape)) {
    if (!*mesh) throw Error(where + ": the mesh is null");
    if ((*mesh)->mesh().size() == 0) throw Error(where + ": the mesh has no triangles");
    return;
  }
  std::visit(
      [&](const auto& s) {
        if constexpr (!std::is_same_v<std::decay_t<decltype(s)>, MeshObstacle>) validate(s, where);
      },
      shape);
}

// The box of a bounded obstacle, grown (core::ObstacleRow::lo: no computed test meets the
// obstacle from outside it).
Aabb bounds(const ObstacleShape& shape) {
  const core::ObstacleRow row = detail::rowOf(shape);
  return {Vec3f(row.lo[0], row.lo[1], row.lo[2]), Vec3f(row.hi[0], row.hi[1], row.hi[2])};
}

}  // namespace

Handle Obstacles::add(const ObstacleShape& shape) {
  validateShape(shape, "Obstacles::add: obstacle " + std::to_string(shapes_.size()));
  shapes_.push_back(shape);
  dirty_ = true;
  ++version_;
  return handles_.add();
}

void Obstacles::remove(Handle h) {
  const std::uint32_t i = handles_.remove(h, "Obstacles::remove", "obstacle");
  shapes_[i] = shapes_.back();
  shapes_.pop_back();
  dirty_ = true;
  ++version_;
}

const ObstacleShape& Obstacles::operator[](Handle h) const {
  return shapes_[handles_.index(h, "Obstacles::operator[]", "obstacle")];
}

void Obstacles::update() {
  if (!dirty_) return;
  bounded_.clear(), planes_.clear();
  for (std::uint32_t i = 0; i < shapes_.size(); ++i)
    (std::holds_alternative<Plane>(shapes_[i]) ? planes_ : bounded_).push_back(i);
  treeBuilt_ = bounded_.size() > kFewObstacles;
  boxes_.clear();
  if (treeBuilt_) {
    BoxStream stream;
    for (std::uint32_t i : bounded_)
      boxes_.push_back(bounds(shapes_[i])), stream.push(boxes_.back());
    tree_.build(stream);
  }
  dirty_ = false;
}

bool Obstacles::inside(const Vec3f& p) const {
  for (const ObstacleShape& o : shapes_)
    if (std::visit([&](const auto& s) { return reference::exitOf(s, p).has_value(); }, o))
      return true;
  return false;
}

}  // namespace simdphys
