// The sections of a scene file (sections.hpp): obstacles, particle systems, cloths and rigid
// bodies, each value checked where it is read.
#include "sections.hpp"

#include <memory>

#include "settings.hpp"
#include "simdphys/mesh.hpp"
#include "simdphys/random.hpp"

namespace simdphys::scenefile {
namespace {

// Sizes beyond kMaxElements's rule (sections.hpp).
constexpr std::int64_t kMaxGridSide = 10'000;
constexpr std::int64_t kMaxPyramidBase = 400;  // 21 million boxes

// A spring's stiffness (N/m, or "rigid") and damping, where n has them.
SpringKindSettings springKind(const Node& n) {
  SpringKindSettings s;
  if (auto k = n.find("stiffness"))
    s.stiffness = k->json() == "rigid" ? kRigid : float(k->positive());
  n.read("damping", s.damping, 0, kMaxCoordinate);
  return s;
}

SpringKindSettings springKind(const Node& grid, const char* key) {
  const auto n = grid.find(key);
  if (!n) return {};
  n->keys({"stiffness", "damping"});
  return springKind(*n);
}

// A grid: nx x nz particles in the plane y = center.y, particle (i, j) at
// center + ((i - (nx-1)/2) d, 0, (j - (nz-1)/2) d), computed in double and rounded once (as W3
// places its particles); `pinned` lists [i, j] pairs of infinite mass.
ClothGrid clothGrid(const Node& n) {
  n.keys({"nx", "nz", "center", "spacing", "mass", "pinned", "structural", "shear", "bend"});
  ClothGrid g;
  g.nx = std::size_t(n.require("nx").integer(2, kMaxGridSide));
  g.nz = std::size_t(n.require("nz").integer(2, kMaxGridSide));
  Vec3f center = Vec3f::Zero();
  n.read("center", center);
  const double d = n.require("spacing").positive(1e6);
  float mass = 1;
  n.readPositive("mass", mass);
  for (std::size_t j = 0; j < g.nz; ++j)
    for (std::size_t i = 0; i < g.nx; ++i) {
      const double x = (double(i) - 0.5 * double(g.nx - 1)) * d + double(center.x());
      const double z = (double(j) - 0.5 * double(g.nz - 1)) * d + double(center.z());
      g.positions.emplace_back(float(x), center.y(), float(z));
    }
  g.invMass.assign(g.nx * g.nz, 1 / mass);
  if (auto pins = n.find("pinned"))
    for (std::size_t k = 0, count = pins->size(g.nx * g.nz); k < count; ++k) {
      const Node p = (*pins)[k];
      if (p.size() != 2) p.fail("must be a pair [i, j]");
      const auto i = std::size_t(p[0].integer(0, std::int64_t(g.nx) - 1));
      const auto j = std::size_t(p[1].integer(0, std::int64_t(g.nz) - 1));
      g.invMass[j * g.nx + i] = 0;
    }
  g.structural = springKind(n, "structural");
  g.shear = springKind(n, "shear");
  g.bend = springKind(n, "bend");
  return g;
}

Cloth clothNetwork(const Node& n, const ClothSettings& settings) {
  const Node list = n.require("particles");
  std::vector<Vec3f> positions;
  std::vector<float> invMass;
  for (std::size_t i = 0, count = list.size(kMaxElements); i < count; ++i) {
    const Node p = list[i];
    p.keys({"position", "invMass"});
    float w = 1;
    p.read("invMass", w, 0, kMaxCoordinate);
    positions.push_back(p.require("position").vec3());
    invMass.push_back(w);
  }
  const Node springList = n.require("springs");
  std::vector<Spring> springs;
  for (std::size_t i = 0, count = springList.size(kMaxElements); i < count; ++i) {
    const Node s = springList[i];
    s.keys({"a", "b", "rest", "stiffness", "damping"});
    Spring spring;
    spring.a = std::uint32_t(s.require("a").integer(0, std::int64_t(positions.size()) - 1));
    spring.b = std::uint32_t(s.require("b").integer(0, std::int64_t(positions.size()) - 1));
    if (spring.a == spring.b)
      s.require("b").fail("joins particle " + std::to_string(spring.a) + " to itself");
    // By default at rest where it is built.
    spring.rest =
        float((positions[spring.a].cast<double>() - positions[spring.b].cast<double>()).norm());
    s.read("rest", spring.rest, 0, kMaxCoordinate);
    const SpringKindSettings kind = springKind(s);
    spring.stiffness = kind.stiffness, spring.damping = kind.damping;
    springs.push_back(spring);
  }
  return Cloth(positions, invMass, springs, settings);
}

// A body's fields over `def` (a pyramid's template, or the defaults).
BodyDef body(const Node& n, BodyDef def, bool positioned) {
  if (positioned)
    n.keys({"shape", "halfExtents", "radius", "points", "position", "rotation", "velocity",
            "angularVelocity", "mass", "kinematic", "friction", "restitution"});
  else
    n.keys({"shape", "halfExtents", "radius", "points", "rotation", "velocity", "angularVelocity",
            "mass", "kinematic", "friction", "restitution"});
  if (auto s = n.find("shape")) {
    const std::string shape = s->string();
    if (shape == "box")
      def.shape = BodyShape::kBox;
    else if (shape == "sphere")
      def.shape = BodyShape::kSphere;
    else if (shape == "hull")
      def.shape = BodyShape::kHull;
    else
      s->fail("\"" + shape + "\" is not one of box, sphere, hull");
  }
  if (def.shape == BodyShape::kHull) {
    // The hull of its points, about their centre of mass and in their principal axes: `position`
    // places that frame (rigid/hull.hpp).
    const Node points = n.require("points");
    std::vector<Vec3f> p(points.size(HullShape::kMaxPoints));
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = points[i].vec3(-1e6, 1e6);
    def.hull = within(points, [&] { return std::make_shared<const HullShape>(p, points.where()); });
  } else if (n.find("points")) {
    n.require("points").fail("only a hull has points");
  }
  if (auto h = n.find("halfExtents")) def.halfExtents = h->positiveVec3(1e6);
  n.readPositive("radius", def.radius, 1e6);
  if (positioned) def.position = n.require("position").vec3();
  if (auto r = n.find("rotation")) def.orientation = rotation(*r).cast<float>();
  n.read("velocity", def.velocity);
  n.read("angularVelocity", def.angularVelocity);
  n.read("kinematic", def.kinematic);
  if (!def.kinematic) n.readPositive("mass", def.mass);
  n.read("friction", def.friction, 0, 1e6);
  n.read("restitution", def.restitution, 0, 1);
  return def;
}

// W5's pyramid for any box: layer k = 0 .. base-1 holds (base-k)^2 boxes on a lattice of the
// box's size centred on `center` (the middle of the bottom layer's underside), row by row along z,
// within a row along x; the offsets computed in double and rounded once.
void pyramid(const Node& n, RigidBodies& bodies, SceneFile& scene) {
  n.keys({"base", "center", "body"});
  const int base = int(n.require("base").integer(1, kMaxPyramidBase));
  Vec3f center = Vec3f::Zero();
  n.read("center", center);
  BodyDef def;
  if (auto b = n.find("body")) def = body(*b, def, false);
  if (def.shape != BodyShape::kBox) n.require("body").fail("a pyramid is built of boxes");
  const Vec3d size = 2 * def.halfExtents.cast<double>(), c = center.cast<double>();
  for (int k = 0; k < base; ++k) {
    const int m = base - k;
    const double first = -0.5 * double(m - 1);
    for (int row = 0; row < m; ++row)
      for (int col = 0; col < m; ++col) {
        def.position =
            Vec3f(float(c.x() + (first + col) * size.x()), float(c.y() + (0.5 + k) * size.y()),
                  float(c.z() + (first + row) * size.z()));
        scene.bodies.push_back(within(n, [&] { return bodies.add(def); }));
      }
  }
}

}  // namespace

ObstacleShape obstacle(const Node& n, const std::filesystem::path& folder) {
  const std::string type = n.require("type").string();
  if (type == "plane") {
    n.keys({"type", "normal", "point"});
    const Node normal = n.require("normal");
    const Vec3f nv = normal.vec3();
    if (!(nv.norm() > 0)) normal.fail("must not be zero");
    Vec3f point = Vec3f::Zero();
    n.read("point", point);
    return Plane::fromPointNormal(point, nv);
  }
  if (type == "sphere") {
    n.keys({"type", "center", "radius"});
    return Sphere{n.require("center").vec3(), float(n.require("radius").positive())};
  }
  if (type == "aabb") {
    n.keys({"type", "min", "max"});
    const Vec3f lo = n.require("min").vec3(), hi = n.require("max").vec3();
    if (!(lo.array() <= hi.array()).all()) n.require("max").fail("must be >= min on every axis");
    return Aabb{lo, hi};
  }
  if (type == "box") {
    n.keys({"type", "center", "halfExtents", "rotation"});
    Obb box{n.require("center").vec3(), n.require("halfExtents").positiveVec3()};
    if (auto r = n.find("rotation")) box.axes = rotationMatrix(*r);
    return box;
  }
  if (type == "mesh") {
    n.keys({"type", "obj", "position", "rotation", "scale"});
    const Node obj = n.require("obj");
    Mesh mesh;
    try {
      mesh = loadObj((folder / obj.string()).string());
    } catch (const Error& e) {
      obj.fail(e.what());
    }
    float scale = 1;
    n.readPositive("scale", scale, 1e6);
    Vec3f position = Vec3f::Zero();
    n.read("position", position);
    const Mat3f r = n.find("rotation") ? rotationMatrix(*n.find("rotation")) : Mat3f::Identity();
    for (Vec3f& v : mesh.vertices) v = r * (scale * v) + position;
    try {
      mesh.validate("the placed mesh");
    } catch (const Error& e) {
      n.fail(e.what());
    }
    return std::make_shared<const MeshBvh>(std::move(mesh));
  }
  n.require("type").fail("\"" + type + "\" is not one of plane, sphere, aabb, box, mesh");
}

void particleSystem(const Node& n, World& world, SceneFile& scene) {
  n.keys({"settings", "particles", "emitters"});
  const ParticleSettings settings =
      n.find("settings") ? particleSettings(*n.find("settings")) : ParticleSettings{};
  const Handle h = world.addParticles(settings);
  scene.particleSystems.push_back(h);
  ParticleSystem& system = world.particles(h);
  if (auto list = n.find("particles"))
    for (std::size_t i = 0, count = list->size(kMaxElements); i < count; ++i) {
      const Node p = (*list)[i];
      p.keys({"position", "velocity", "invMass"});
      Vec3f v = Vec3f::Zero();
      float invMass = 1;
      p.read("velocity", v);
      p.read("invMass", invMass, 0, kMaxCoordinate);
      system.add(p.require("position").vec3(), v, invMass);
    }
  // Emitters place their particles when the scene is built: `count` points drawn uniformly in
  // the box [min, max] from `seed` (x, y, z per particle, as workload W4 draws them).
  if (auto list = n.find("emitters"))
    for (std::size_t i = 0, count = list->size(1000); i < count; ++i) {
      const Node e = (*list)[i];
      e.keys({"count", "seed", "min", "max", "velocity", "invMass"});
      const std::size_t particles = std::size_t(e.require("count").integer(0, kMaxElements));
      if (system.size() + particles > std::size_t(kMaxElements))
        e.require("count").fail("takes the system past " + std::to_string(kMaxElements) +
                                " particles");
      Random r(std::uint64_t(e.require("seed").integer(0, INT64_MAX)));
      const Vec3f lo = e.require("min").vec3(), hi = e.require("max").vec3();
      if (!(lo.array() <= hi.array()).all()) e.require("max").fail("must be >= min on every axis");
      Vec3f v = Vec3f::Zero();
      float invMass = 1;
      e.read("velocity", v);
      e.read("invMass", invMass, 0, kMaxCoordinate);
      system.reserve(system.size() + particles);
      for (std::size_t k = 0; k < particles; ++k) {
        const float x = r.uniform(lo.x(), hi.x());
        const float y = r.uniform(lo.y(), hi.y());
        const float z = r.uniform(lo.z(), hi.z());
        system.add({x, y, z}, v, invMass);
      }
    }
}

void cloth(const Node& n, World& world, SceneFile& scene) {
  n.keys({"settings", "grid", "particles", "springs"});
  const ClothSettings settings =
      n.find("settings") ? clothSettings(*n.find("settings")) : ClothSettings{};
  if (auto g = n.find("grid")) {
    if (n.find("particles") || n.find("springs"))
      n.fail("give either a grid or particles and springs");
    scene.cloths.push_back(
        world.addCloth(within(n, [&] { return Cloth::grid(clothGrid(*g), settings); })));
  } else {
    scene.cloths.push_back(world.addCloth(within(n, [&] { return clothNetwork(n, settings); })));
  }
}

void rigid(const Node& n, World& world, SceneFile& scene) {
  n.keys({"settings", "bodies", "pyramids"});
  RigidBodies& bodies = world.bodies();
  if (auto s = n.find("settings")) bodies.setSettings(rigidSettings(*s));
  if (auto list = n.find("bodies"))
    for (std::size_t i = 0, count = list->size(kMaxElements); i < count; ++i) {
      const Node b = (*list)[i];
      scene.bodies.push_back(within(b, [&] { return bodies.add(body(b, BodyDef{}, true)); }));
    }
  if (auto list = n.find("pyramids"))
    for (std::size_t i = 0, count = list->size(1000); i < count; ++i)
      pyramid((*list)[i], bodies, scene);
}

}  // namespace simdphys::scenefile
