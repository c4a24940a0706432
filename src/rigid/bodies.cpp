// RigidBodies (rigid.hpp): settings, bodies as dense streams behind handles, their validation and
// inertia.
#include <algorithm>
#include <cmath>
#include <string>

#include "simdphys/rigid.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

namespace F = fields;

const char* toString(ContactModel model) {
  switch (model) {
    case ContactModel::kSoftStep:
      return "soft step";
    case ContactModel::kBaumgarte:
      return "Baumgarte";
    case ContactModel::kProjection:
      return "linear projection";
  }
  return "unknown contact model";
}

void validate(const RigidSettings& s, const std::string& where) {
  using detail::require;
  const auto m = static_cast<unsigned>(s.model);
  require(m <= unsigned(ContactModel::kProjection), m, where, "model", "not a ContactModel");
  detail::requireFiniteField(s.gravity, where, "gravity");
  require(s.substeps >= 1 && s.substeps <= 64, s.substeps, where, "substeps", "must be in [1, 64]");
  require(s.iterations >= 1 && s.iterations <= 256, s.iterations, where, "iterations",
          "must be in [1, 256]");
  const auto positive = [&](float x, const char* field, float max) {
    require(x > 0 && x <= max, x, where, field, "must be positive and in range");
  };
  positive(s.contactHertz, "contactHertz", 1e6f);
  positive(s.contactDampingRatio, "contactDampingRatio", 1e6f);
  positive(s.maxPushSpeed, "maxPushSpeed", 1e6f);
  require(s.baumgarte > 0 && s.baumgarte <= 1, s.baumgarte, where, "baumgarte",
          "must be in (0, 1]");
  require(s.projection > 0 && s.projection <= 1, s.projection, where, "projection",
          "must be in (0, 1]");
  const auto nonNegative = [&](float x, const char* field) {
    require(x >= 0 && x <= 1e6f, x, where, field, "must be finite and >= 0");
  };
  nonNegative(s.linearSlop, "linearSlop");
  nonNegative(s.speculativeDistance, "speculativeDistance");
  nonNegative(s.restitutionThreshold, "restitutionThreshold");
  nonNegative(s.linearDamping, "linearDamping");
  nonNegative(s.angularDamping, "angularDamping");
  nonNegative(s.sleepSpeed, "sleepSpeed");
  nonNegative(s.timeToSleep, "timeToSleep");
}

RigidBodies::RigidBodies(const RigidSettings& settings) {
  validate(settings, "RigidBodies");
  settings_ = settings;
}

void RigidBodies::setSettings(const RigidSettings& settings) {
  validate(settings, "RigidBodies::setSettings");
  settings_ = settings;
}

std::uint32_t RigidBodies::require(Handle h, const char* where) const {
  return handles_.index(h, where, "body");
}

std::uint32_t RigidBodies::index(Handle h) const { return require(h, "RigidBodies::index"); }

Vec3f RigidBodies::loadVec(std::size_t f, std::size_t i) const {
  return {value(f, i), value(f + 1, i), value(f + 2, i)};
}

void RigidBodies::storeVec(std::size_t f, std::size_t i, const Vec3f& v) {
  for (std::size_t k = 0; k < 3; ++k) paddedData(f + k)[i] = v[Eigen::Index(k)];
}

namespace {

void requireOrientation(const Quatf& q, const std::string& where) {
  detail::requireFiniteField(q.coeffs(), where, "orientation");
  detail::require(std::abs(q.norm() - 1) <= 1e-3f, q.norm(), where, "|orientation|",
                  "must be 1 within 1e-3 (a unit quaternion)");
}

}  // namespace

Handle RigidBodies::add(const BodyDef& d) {
  const std::string where = "RigidBodies::add: body " + std::to_string(size());
  using detail::require;
  const auto shape = static_cast<unsigned>(d.shape);
  require(shape <= unsigned(BodyShape::kHull), shape, where, "shape", "not a BodyShape");
  if (d.shape == BodyShape::kHull && !d.hull)
    throw Error(where + ": hull is empty; a hull body needs its HullShape");
  detail::requireFiniteField(d.position, where, "position");
  requireOrientation(d.orientation, where);
  detail::requireFiniteField(d.velocity, where, "velocity");
  detail::requireFiniteField(d.angularVelocity, where, "angularVelocity");
  Vec3f half;
  if (d.shape == BodyShape::kBox) {
    for (int k = 0; k < 3; ++k)
      require(d.halfExtents[k] > 0 && d.halfExtents[k] <= 1e6f, d.halfExtents[k], where,
              k == 0   ? "halfExtents.x"
              : k == 1 ? "halfExtents.y"
                       : "halfExtents.z",
              "must be in (0, 1e6] m");
    half = d.halfExtents;
  } else if (d.shape == BodyShape::kHull) {
    half = d.hull->halfExtents();
  } else {
    require(d.radius > 0 && d.radius <= 1e6f, d.radius, where, "radius", "must be in (0, 1e6] m");
    half = {d.radius, 0, 0};
  }
  if (!d.kinematic)
    require(d.mass > 0 && std::isfinite(d.mass), d.mass, where, "mass",
            "must be finite and > 0 for a dynamic body (kinematic = true for an immovable one)");
  require(d.friction >= 0 && std::isfinite(d.friction), d.friction, where, "friction",
          "must be finite and >= 0");
  require(d.restitution >= 0 && d.restitution <= 1, d.restitution, where, "restitution",
          "must be in [0, 1]");

  // Inertia of a solid box (m/3 (b^2 + c^2) with half extents), sphere (2/5 m r^2) or hull (its
  // principal moments per unit mass times m).
  Vec3f invInertia = Vec3f::Zero();
  const float invMass = d.kinematic ? 0.0f : 1.0f / d.mass;
  if (!d.kinematic) {
    const Vec3d h = half.cast<double>(), h2 = h.cwiseProduct(h);
    const Vec3d inertia =
        d.shape == BodyShape::kBox
            ? Vec3d(Vec3d(h2.y() + h2.z(), h2.x() + h2.z(), h2.x() + h2.y()) * (double(d.mass) / 3))
        : d.shape == BodyShape::kHull ? Vec3d(d.hull->inertia().cast<double>() * double(d.mass))
                                      : Vec3d(Vec3d::Constant(0.4 * double(d.mass) * h2.x()));
    invInertia = inertia.cwiseInverse().cast<float>();
    require(invInertia.allFinite(), d.mass, where, "mass", "gives an inertia out of range");
  }
  float hull = 0;
  if (d.shape == BodyShape::kHull) {
    const auto known = std::find(hulls_.begin(), hulls_.end(), d.hull);
    hull = float(known - hulls_.begin());
    if (known == hulls_.end()) hulls_.push_back(d.hull);
  }
  const Quatf q = d.orientation.normalized();
  append({d.position.x(),
          d.position.y(),
          d.position.z(),
          q.x(),
          q.y(),
          q.z(),
          q.w(),
          d.velocity.x(),
          d.velocity.y(),
          d.velocity.z(),
          d.angularVelocity.x(),
          d.angularVelocity.y(),
          d.angularVelocity.z(),
          invMass,
          invInertia.x(),
          invInertia.y(),
          invInertia.z(),
          float(shape),
          half.x(),
          half.y(),
          half.z(),
          d.friction,
          d.restitution,
          0,
          0,
          0,
          0,
          0,
          0,
          0,
          0,
          hull});
  return handles_.add();
}

void RigidBodies::remove(Handle h) {
  const std::uint32_t i = require(h, "RigidBodies::remove");
  wake(i);  // what it held up falls
  eraseSwap(handles_.remove(h, "RigidBodies::remove", "body"));
  // Its contacts leave the cache: a body added later may take its slot.
  const auto involved = [&](const auto& m) {
    return std::uint32_t(m.key >> 32) == h.slot || std::uint32_t(m.key) == h.slot;
  };
  std::erase_if(cache_.manifolds, involved);
  std::erase_if(cache_.pairs, involved);
}

void RigidBodies::setVec(Handle h, const char* where, std::size_t f, const char* name,
                         const Vec3f& value) {
  const std::uint32_t i = require(h, where);
  detail::requireFiniteField(value, where, name);
  wake(i);
  storeVec(f, i, value);
}

std::span<float> RigidBodies::writableField(std::size_t f) {
  if (f > F::Body::wz)
    throw Error("RigidBodies::writableField: field " + std::to_string(f) +
                " is not a position, orientation or velocity");
  for (std::uint32_t i = 0; i < size(); ++i) wake(i);
  return writable(f);
}

void RigidBodies::checkFields(const std::string& where) const {
  static constexpr const char* kNames[] = {"x",  "y",  "z",  "qx", "qy", "qz", "qw",  // x .. wz
                                           "vx", "vy", "vz", "wx", "wy", "wz"};
  requireInRange(kNames, where, "body");
  for (std::uint32_t i = 0; i < size(); ++i)
    requireOrientation(Quatf(value(F::Body::qw, i), value(F::Body::qx, i), value(F::Body::qy, i),
                             value(F::Body::qz, i)),
                       where + ": body " + std::to_string(i));
}

void RigidBodies::wake(std::uint32_t i) {
  const float island = value(F::Body::island, i);
  if (island == 0) return;
  for (std::size_t j = 0; j < size(); ++j)
    if (value(F::Body::island, j) == island) {
      paddedData(F::Body::island)[j] = 0;
      paddedData(F::Body::sleepTime)[j] = 0;
    }
}

bool RigidBodies::asleep(Handle h) const {
  return value(F::Body::island, require(h, "RigidBodies::asleep")) != 0;
}

std::size_t RigidBodies::awakeCount() const {
  std::size_t n = 0;
  for (std::size_t i = 0; i < size(); ++i) n += value(F::Body::island, i) == 0 ? 1 : 0;
  return n;
}

Vec3f RigidBodies::position(Handle h) const {
  return loadVec(F::Body::x, require(h, "RigidBodies::position"));
}
Vec3f RigidBodies::velocity(Handle h) const {
  return loadVec(F::Body::vx, require(h, "RigidBodies::velocity"));
}
Vec3f RigidBodies::angularVelocity(Handle h) const {
  return loadVec(F::Body::wx, require(h, "RigidBodies::angularVelocity"));
}
Quatf RigidBodies::orientation(Handle h) const {
  const std::uint32_t i = require(h, "RigidBodies::orientation");
  return Quatf(value(F::Body::qw, i), value(F::Body::qx, i), value(F::Body::qy, i),
               value(F::Body::qz, i));
}
bool RigidBodies::kinematic(Handle h) const {
  return value(F::Body::invMass, require(h, "RigidBodies::kinematic")) == 0;
}

Obb RigidBodies::box(Handle h) const {
  const std::uint32_t i = require(h, "RigidBodies::box");
  if (value(F::Body::shape, i) != float(BodyShape::kBox))
    throw Error("RigidBodies::box: body " + std::to_string(i) + " is not a box");
  return {loadVec(F::Body::x, i), loadVec(F::Body::ex, i), orientation(h).toRotationMatrix()};
}

Sphere RigidBodies::sphere(Handle h) const {
  const std::uint32_t i = require(h, "RigidBodies::sphere");
  if (value(F::Body::shape, i) != float(BodyShape::kSphere))
    throw Error("RigidBodies::sphere: body " + std::to_string(i) + " is not a sphere");
  return {loadVec(F::Body::x, i), value(F::Body::ex, i)};
}

std::shared_ptr<const HullShape> RigidBodies::hull(Handle h) const {
  const std::uint32_t i = require(h, "RigidBodies::hull");
  if (value(F::Body::shape, i) != float(BodyShape::kHull))
    throw Error("RigidBodies::hull: body " + std::to_string(i) + " is not a hull");
  return hulls_[std::size_t(value(F::Body::hull, i))];
}

void RigidBodies::setPosition(Handle h, const Vec3f& p) {
  setVec(h, "RigidBodies::setPosition", F::Body::x, "position", p);
}

void RigidBodies::setOrientation(Handle h, const Quatf& q) {
  const std::uint32_t i = require(h, "RigidBodies::setOrientation");
  requireOrientation(q, "RigidBodies::setOrientation");
  wake(i);
  const Quatf u = q.normalized();
  storeVec(F::Body::qx, i, u.vec());
  paddedData(F::Body::qw)[i] = u.w();
}

void RigidBodies::setVelocity(Handle h, const Vec3f& v) {
  setVec(h, "RigidBodies::setVelocity", F::Body::vx, "velocity", v);
}

void RigidBodies::setAngularVelocity(Handle h, const Vec3f& w) {
  setVec(h, "RigidBodies::setAngularVelocity", F::Body::wx, "angularVelocity", w);
}

void RigidBodies::applyImpulse(Handle h, const Vec3f& impulse, const Vec3f& point) {
  const char* where = "RigidBodies::applyImpulse";
  const std::uint32_t i = require(h, where);
  detail::requireFiniteField(impulse, where, "impulse");
  detail::requireFiniteField(point, where, "point");
  const float invMass = value(F::Body::invMass, i);
  if (invMass == 0) return;  // kinematic: nothing pushes it
  const Mat3f R = orientation(h).toRotationMatrix();
  const Mat3f invInertia = R * loadVec(F::Body::invIx, i).asDiagonal() * R.transpose();
  const Vec3f v = loadVec(F::Body::vx, i) + invMass * impulse;
  const Vec3f w =
      loadVec(F::Body::wx, i) + invInertia * (point - loadVec(F::Body::x, i)).cross(impulse);
  detail::requireFiniteField(v, where, "resulting velocity");
  detail::requireFiniteField(w, where, "resulting angular velocity");
  wake(i);
  storeVec(F::Body::vx, i, v);
  storeVec(F::Body::wx, i, w);
}

void RigidBodies::setForce(Handle h, const Vec3f& f) {
  setVec(h, "RigidBodies::setForce", F::Body::fx, "force", f);
}

void RigidBodies::setTorque(Handle h, const Vec3f& t) {
  setVec(h, "RigidBodies::setTorque", F::Body::tx, "torque", t);
}

}  // namespace simdphys
