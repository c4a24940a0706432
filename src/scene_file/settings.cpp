#include "settings.hpp"

#include <utility>

namespace simdphys::scenefile {
namespace {

// One of a set of names, as its enum value; else an error listing the names.
template <class E>
E choice(const Node& n, std::initializer_list<std::pair<const char*, E>> names) {
  const std::string s = n.string();
  std::string list;
  for (const auto& [name, value] : names) {
    if (s == name) return value;
    list += (list.empty() ? "" : ", ") + std::string(name);
  }
  n.fail("\"" + s + "\" is not one of " + list);
}

// Counts are read as any int; the library's validate() then checks each against its range, its
// message naming the block's place and the field ("file: /rigid/settings: substeps is 100, ...").
constexpr int kAnyInt = 1 << 30;

}  // namespace

WorldSettings worldSettings(const Node& n) {
  WorldSettings s;
  n.read("timeStep", s.timeStep);
  n.read("substeps", s.substeps, -kAnyInt, kAnyInt);
  n.read("threads", s.threads, -kAnyInt, kAnyInt);
  validate(s, n.where().c_str());
  return s;
}

ParticleSettings particleSettings(const Node& n) {
  n.keys({"integrator", "gravity", "damping", "drag", "restitution", "friction",
          "restitutionThreshold", "skin", "maxBounces"});
  ParticleSettings s;
  if (auto i = n.find("integrator"))
    s.integrator = choice<Integrator>(*i, {{"explicitEuler", Integrator::kExplicitEuler},
                                           {"semiImplicitEuler", Integrator::kSemiImplicitEuler},
                                           {"velocityVerlet", Integrator::kVelocityVerlet},
                                           {"positionVerlet", Integrator::kPositionVerlet}});
  n.read("gravity", s.gravity);
  n.read("damping", s.damping);
  n.read("drag", s.drag);
  n.read("restitution", s.restitution);
  n.read("friction", s.friction);
  n.read("restitutionThreshold", s.restitutionThreshold);
  n.read("skin", s.skin);
  n.read("maxBounces", s.maxBounces, -kAnyInt, kAnyInt);
  validate(s, n.where());
  return s;
}

ClothSettings clothSettings(const Node& n) {
  n.keys({"model", "gravity", "substeps", "damping", "margin", "friction", "tethers", "penalty"});
  ClothSettings s;
  if (auto m = n.find("model"))
    s.model = choice<ClothModel>(
        *m, {{"xpbd", ClothModel::kXpbd}, {"massSpring", ClothModel::kMassSpring}});
  n.read("gravity", s.gravity);
  n.read("substeps", s.substeps, -kAnyInt, kAnyInt);
  n.read("damping", s.damping);
  n.read("margin", s.margin);
  n.read("friction", s.friction);
  n.read("tethers", s.tethers);
  n.read("penalty", s.penalty);
  validate(s, n.where());
  return s;
}

RigidSettings rigidSettings(const Node& n) {
  n.keys({"model", "gravity", "substeps", "iterations", "contactHertz", "contactDampingRatio",
          "maxPushSpeed", "baumgarte", "projection", "linearSlop", "speculativeDistance",
          "restitutionThreshold", "linearDamping", "angularDamping", "warmStarting",
          "reuseManifolds", "sleeping", "sleepSpeed", "timeToSleep"});
  RigidSettings s;
  if (auto m = n.find("model"))
    s.model = choice<ContactModel>(*m, {{"softStep", ContactModel::kSoftStep},
                                        {"baumgarte", ContactModel::kBaumgarte},
                                        {"projection", ContactModel::kProjection}});
  n.read("gravity", s.gravity);
  n.read("substeps", s.substeps, -kAnyInt, kAnyInt);
  n.read("iterations", s.iterations, -kAnyInt, kAnyInt);
  n.read("contactHertz", s.contactHertz);
  n.read("contactDampingRatio", s.contactDampingRatio);
  n.read("maxPushSpeed", s.maxPushSpeed);
  n.read("baumgarte", s.baumgarte);
  n.read("projection", s.projection);
  n.read("linearSlop", s.linearSlop);
  n.read("speculativeDistance", s.speculativeDistance);
  n.read("restitutionThreshold", s.restitutionThreshold);
  n.read("linearDamping", s.linearDamping);
  n.read("angularDamping", s.angularDamping);
  n.read("warmStarting", s.warmStarting);
  n.read("reuseManifolds", s.reuseManifolds);
  n.read("sleeping", s.sleeping);
  n.read("sleepSpeed", s.sleepSpeed);
  n.read("timeToSleep", s.timeToSleep);
  validate(s, n.where());
  return s;
}

Quatd rotation(const Node& n) {
  n.keys({"axis", "angle", "quaternion"});
  if (auto q = n.find("quaternion")) {
    if (n.find("axis") || n.find("angle")) n.fail("give either quaternion or axis and angle");
    if (q->size() != 4) q->fail("must be an array of 4 numbers (x, y, z, w)");
    const Quatd r((*q)[3].number(), (*q)[0].number(), (*q)[1].number(), (*q)[2].number());
    if (!(r.norm() > 1e-9)) q->fail("must not be zero");
    return r.normalized();
  }
  const Node axisNode = n.require("axis");
  const Vec3d axis = axisNode.vec3().cast<double>();
  if (!(axis.norm() > 1e-9)) axisNode.fail("must not be zero");
  return Quatd(Eigen::AngleAxisd(n.require("angle").number(-1e6, 1e6), axis.normalized()));
}

Mat3f rotationMatrix(const Node& n) {
  // The axis-angle form through math.hpp's axisAngle, as the workloads compute their rotations.
  if (n.find("axis")) {
    rotation(n);  // the checks
    const Vec3d axis = n.require("axis").vec3().cast<double>();
    return axisAngle(axis, n.require("angle").number()).cast<float>();
  }
  return rotation(n).toRotationMatrix().cast<float>();
}

}  // namespace simdphys::scenefile
