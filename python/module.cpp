// The simdphys Python module (docs/python.md): worlds loaded from scene files or built here,
// stepped, their particle and body streams read and written as numpy arrays without copies
// (checked before every step), snapshots, batch ray casts and overlap queries from numpy arrays,
// and the execution paths. simdphys::Error is raised as simdphys.Error (a ValueError).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <memory>
#include <optional>

#include "simdphys/batch.hpp"
#include "simdphys/bvh.hpp"
#include "simdphys/measures.hpp"
#include "simdphys/mesh_bvh.hpp"
#include "simdphys/scene_file.hpp"
#include "simdphys/snapshot.hpp"

namespace py = pybind11;
using namespace simdphys;

namespace {

// A world as Python holds it. Views share its streams' memory; a stream that grew would move
// and leave them dangling, so once a view was taken nothing more can be added.
struct PyWorld {
  World world;
  bool viewed = false;
  void growable(const char* what) const {
    if (viewed)
      throw Error(std::string(what) +
                  ": the world's streams are viewed by numpy arrays, which adding would leave "
                  "dangling; build the world first, then take views");
  }
  // The streams numpy may have written, checked: an error names the system or the bodies, the
  // element and the field, and nothing has moved.
  void step(int frames) {
    for (int f = 0; f < frames; ++f) {
      if (viewed) {
        for (std::size_t s = 0; s < world.particleSystemCount(); ++s)
          world.particles(world.particleSystemHandle(s))
              .checkFields("World.step: particle system " + std::to_string(s));
        world.bodies().checkFields("World.step: bodies");
      }
      py::gil_scoped_release release;
      world.step();
    }
  }
};

// A 1-D float32 view of a live field; `owner` keeps the world alive while the array lives.
py::array_t<float> view(std::span<float> field, py::object owner) {
  return py::array_t<float>({field.size()}, {sizeof(float)}, field.data(), owner);
}

std::vector<Vec3f> points(const py::array_t<float, py::array::c_style | py::array::forcecast>& a,
                          const char* what) {
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw Error(std::string(what) + ": must be an array of shape (n, 3)");
  std::vector<Vec3f> out(std::size_t(a.shape(0)));
  auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) out[std::size_t(i)] = {r(i, 0), r(i, 1), r(i, 2)};
  return out;
}

py::array_t<float> toArray(const std::vector<Vec3f>& p) {
  py::array_t<float> out({py::ssize_t(p.size()), py::ssize_t(3)});
  auto w = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < 3; ++k) w(py::ssize_t(i), k) = p[i][k];
  return out;
}

// The views of a world's particle system or bodies, by field name.
template <class Set, class Fields>
py::dict views(Set& set, py::object owner,
               std::initializer_list<std::pair<const char*, std::size_t>> names) {
  py::dict d;
  for (const auto& [name, f] : names) d[name] = view(set.writableField(f), owner);
  return d;
}

void bindWorld(py::module_& m) {
  py::class_<PyWorld, std::shared_ptr<PyWorld>>(m, "World", "A simdphys World (world.hpp)")
      .def(py::init([](float timeStep, int substeps, int threads) {
             return std::make_shared<PyWorld>(
                 PyWorld{World(WorldSettings{timeStep, substeps, threads})});
           }),
           py::arg("time_step") = 1.0f / 60, py::arg("substeps") = 1, py::arg("threads") = 0)
      .def("step", &PyWorld::step, py::arg("frames") = 1,
           "Steps the world; first checks what numpy views wrote (raises simdphys.Error)")
      .def_property_readonly("time_step",
                             [](const PyWorld& w) { return w.world.settings().timeStep; })
      .def(
          "add_plane",
          [](PyWorld& w, const Vec3f& normal, const Vec3f& point) {
            w.world.obstacles().add(Plane::fromPointNormal(point, normal));
          },
          py::arg("normal"), py::arg("point") = Vec3f::Zero().eval())
      .def(
          "add_sphere_obstacle",
          [](PyWorld& w, const Vec3f& c, float r) {
            w.world.obstacles().add(Sphere{c, r});
          },
          py::arg("center"), py::arg("radius"))
      .def(
          "add_box_obstacle",
          [](PyWorld& w, const Vec3f& c, const Vec3f& h) {
            w.world.obstacles().add(Obb{c, h});
          },
          py::arg("center"), py::arg("half_extents"))
      .def(
          "add_particles",
          [](PyWorld& w, const py::array_t<float, py::array::c_style | py::array::forcecast>& p,
             float restitution, float damping) {
            w.growable("World.add_particles");
            ParticleSettings s;
            s.restitution = restitution, s.damping = damping;
            const Handle h = w.world.addParticles(s);
            ParticleSystem& system = w.world.particles(h);
            const std::vector<Vec3f> positions = points(p, "World.add_particles: positions");
            system.reserve(positions.size());
            try {
              for (const Vec3f& x : positions) system.add(x);
            } catch (...) {
              w.world.removeParticles(h);  // nothing half built
              throw;
            }
            return w.world.particleSystemCount() - 1;
          },
          py::arg("positions"), py::arg("restitution") = 0.5f, py::arg("damping") = 1.0f,
          "Adds a particle system at these (n, 3) positions; returns its index")
      .def(
          "add_body",
          [](PyWorld& w, const std::string& shape, const Vec3f& position, const Vec3f& halfExtents,
             float radius, float mass, const Vec3f& velocity, bool kinematic, float friction,
             float restitution,
             const std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>>&
                 hullPoints) {
            w.growable("World.add_body");
            BodyDef d;
            if (shape != "box" && shape != "sphere" && shape != "hull")
              throw Error("World.add_body: shape must be \"box\", \"sphere\" or \"hull\", got \"" +
                          shape + "\"");
            d.shape = shape == "box"      ? BodyShape::kBox
                      : shape == "sphere" ? BodyShape::kSphere
                                          : BodyShape::kHull;
            if ((d.shape == BodyShape::kHull) != hullPoints.has_value())
              throw Error("World.add_body: points are given for a hull, and only for a hull");
            if (hullPoints)
              d.hull = std::make_shared<const HullShape>(
                  points(*hullPoints, "World.add_body: points"), "World.add_body: points");
            d.position = position, d.halfExtents = halfExtents, d.radius = radius, d.mass = mass;
            d.velocity = velocity, d.kinematic = kinematic, d.friction = friction;
            d.restitution = restitution;
            w.world.bodies().add(d);
            return w.world.bodies().size() - 1;
          },
          py::arg("shape") = "box", py::arg("position") = Vec3f::Zero().eval(),
          py::arg("half_extents") = Vec3f(0.5f, 0.5f, 0.5f), py::arg("radius") = 0.5f,
          py::arg("mass") = 1.0f, py::arg("velocity") = Vec3f::Zero().eval(),
          py::arg("kinematic") = false, py::arg("friction") = 0.6f, py::arg("restitution") = 0.0f,
          py::arg("points") = py::none(),
          "Adds a rigid body (a hull: the convex hull of `points`, an (n, 3) array, placed by its "
          "centre of mass and principal axes); returns its index")
      .def_property_readonly("particle_system_count",
                             [](const PyWorld& w) { return w.world.particleSystemCount(); })
      .def_property_readonly("body_count", [](const PyWorld& w) { return w.world.bodies().size(); })
      .def_property_readonly("cloth_count", [](const PyWorld& w) { return w.world.clothCount(); })
      .def(
          "particles",
          [](const std::shared_ptr<PyWorld>& w, std::size_t i) {
            if (i >= w->world.particleSystemCount())
              throw Error("World.particles: no particle system " + std::to_string(i));
            w->viewed = true;
            ParticleSystem& s = w->world.particles(w->world.particleSystemHandle(i));
            namespace F = fields;
            return views<ParticleSystem, F::Particle>(s, py::cast(w),
                                                      {{"x", F::Particle::x},
                                                       {"y", F::Particle::y},
                                                       {"z", F::Particle::z},
                                                       {"vx", F::Particle::vx},
                                                       {"vy", F::Particle::vy},
                                                       {"vz", F::Particle::vz}});
          },
          py::arg("system") = 0,
          "System i's streams as float32 numpy views (no copy): x, y, z, vx, vy, vz")
      .def(
          "bodies",
          [](const std::shared_ptr<PyWorld>& w) {
            w->viewed = true;
            namespace F = fields;
            return views<RigidBodies, F::Body>(w->world.bodies(), py::cast(w),
                                               {{"x", F::Body::x},
                                                {"y", F::Body::y},
                                                {"z", F::Body::z},
                                                {"qx", F::Body::qx},
                                                {"qy", F::Body::qy},
                                                {"qz", F::Body::qz},
                                                {"qw", F::Body::qw},
                                                {"vx", F::Body::vx},
                                                {"vy", F::Body::vy},
                                                {"vz", F::Body::vz},
                                                {"wx", F::Body::wx},
                                                {"wy", F::Body::wy},
                                                {"wz", F::Body::wz}});
          },
          "The bodies' streams as float32 numpy views (no copy); writing wakes every body")
      .def(
          "cloth_positions",
          [](const PyWorld& w, std::size_t i) {
            if (i >= w.world.clothCount())
              throw Error("World.cloth_positions: no cloth " + std::to_string(i));
            return toArray(w.world.cloth(w.world.clothHandle(i)).positions());
          },
          py::arg("cloth") = 0, "Cloth i's particle positions, an (n, 3) copy")
      .def("measures",
           [](const PyWorld& w) {
             // Of the present state alone: no start to measure displacement from.
             const WorldMeasures measured = WorldMonitor(w.world).measure(w.world);
             py::dict d;
             py::list particles, cloths;
             for (const ParticleMeasures& p : measured.particles)
               particles.append(py::dict(py::arg("count") = p.count, py::arg("inside") = p.inside,
                                         py::arg("mean_height") = p.meanHeight,
                                         py::arg("finite") = p.finite));
             for (const ClothMeasures& c : measured.cloths)
               cloths.append(py::dict(py::arg("mean_stretch") = c.stretch.mean,
                                      py::arg("max_stretch") = c.stretch.max,
                                      py::arg("finite") = c.finite));
             d["particles"] = particles;
             d["cloths"] = cloths;
             d["deepest_body_penetration"] = w.world.bodies().deepestPenetration();
             return d;
           })
      .def(
          "snapshot",
          [](const PyWorld& w) {
            const std::vector<std::byte> b = snapshot(w.world);
            return py::bytes(reinterpret_cast<const char*>(b.data()), b.size());
          },
          "The world's whole state as bytes (snapshot.hpp)")
      .def_static(
          "restore",
          [](const py::bytes& b) {
            const std::string_view s = b;
            return std::make_shared<PyWorld>(
                PyWorld{restore(std::as_bytes(std::span(s.data(), s.size())))});
          },
          "A world from snapshot() bytes; raises simdphys.Error if they are damaged");
}

void bindScene(py::module_& m) {
  m.def(
      "load_scene",
      [](const std::filesystem::path& file) {
        SceneFile scene = loadScene(file);
        py::dict d;
        d["world"] = std::make_shared<PyWorld>(PyWorld{std::move(scene.world)});
        d["name"] = scene.name;
        d["description"] = scene.description;
        d["frames"] = scene.frames;
        d["path"] = scene.path;
        return d;
      },
      py::arg("file"),
      "Loads a scene file (docs/scenes.md): a dict of world, name, description, frames, path");
}

void bindBatch(py::module_& m) {
  m.def(
      "run_batch",
      [](const std::filesystem::path& file, int threads) {
        const std::vector<BatchJob> jobs = loadBatch(file);
        std::vector<BatchResult> results;
        {
          py::gil_scoped_release release;
          results = runBatch(jobs, threads);
        }
        py::list out;
        for (const BatchResult& r : results) {
          py::dict d;
          d["job"] = r.job, d["frames"] = r.frames, d["seconds"] = r.seconds;
          d["state_hash"] = r.stateHash, d["failed"] = bool(r.failed),
          d["error"] = std::string(r.error);
          d["bodies"] = r.bodies, d["max_displacement"] = r.maxDisplacement;
          d["deepest_body_penetration"] = r.deepestBodyPenetration,
          d["standing"] = bool(r.standing);
          d["cloth_mean_stretch"] = r.clothMeanStretch;
          d["cloth_deepest_penetration"] = r.clothDeepestPenetration;
          d["particles"] = r.particles, d["particles_inside"] = r.particlesInside;
          d["finite"] = bool(r.finite);
          out.append(d);
        }
        return out;
      },
      py::arg("file"), py::arg("threads") = 0,
      "Runs a batch file's jobs a job a thread (docs/batch.md): a list of result dicts");
}

void bindQueries(py::module_& m) {
  using Floats = py::array_t<float, py::array::c_style | py::array::forcecast>;
  using Indices = py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>;
  py::class_<MeshBvh, std::shared_ptr<MeshBvh>>(m, "Mesh",
                                                "A triangle mesh with its BVH (mesh_bvh.hpp)")
      .def(py::init([](const Floats& vertices, const Indices& triangles) {
             Mesh mesh;
             mesh.vertices = points(vertices, "Mesh: vertices");
             if (triangles.ndim() != 2 || triangles.shape(1) != 3)
               throw Error("Mesh: triangles must be an array of shape (m, 3)");
             auto t = triangles.unchecked<2>();
             for (py::ssize_t i = 0; i < triangles.shape(0); ++i)
               mesh.triangles.push_back({t(i, 0), t(i, 1), t(i, 2)});
             return std::make_shared<MeshBvh>(std::move(mesh));  // validates it
           }),
           py::arg("vertices"), py::arg("triangles"))
      .def(
          "raycast",
          [](const MeshBvh& bvh, const Floats& origins, const Floats& directions) {
            const std::vector<Vec3f> o = points(origins, "Mesh.raycast: origins");
            const std::vector<Vec3f> d = points(directions, "Mesh.raycast: directions");
            if (o.size() != d.size())
              throw Error("Mesh.raycast: origins and directions differ in count");
            RayStream rays;
            for (std::size_t i = 0; i < o.size(); ++i) rays.push({o[i], d[i]});
            std::vector<ElementHit> hits(o.size());
            {
              py::gil_scoped_release release;
              bvh.raycast(rays, hits);
            }
            py::array_t<float> t(py::ssize_t(hits.size()));
            py::array_t<std::uint32_t> id(py::ssize_t(hits.size()));
            for (std::size_t i = 0; i < hits.size(); ++i)
              t.mutable_at(py::ssize_t(i)) = hits[i].t,
              id.mutable_at(py::ssize_t(i)) = hits[i].index;
            return py::make_tuple(t, id);
          },
          py::arg("origins"), py::arg("directions"),
          "Closest hits of (n, 3) rays: (t, triangle), t = inf and triangle = 2**32-1 for a miss")
      .def(
          "overlap_sphere",
          [](const MeshBvh& bvh, const Vec3f& c, float r) {
            return bvh.overlapping(Sphere{c, r});
          },
          py::arg("center"), py::arg("radius"), "Ids of the triangles the sphere touches");
  py::class_<Bvh, std::shared_ptr<Bvh>>(m, "BoxTree", "A BVH over boxes (bvh.hpp)")
      .def(py::init([](const Floats& lo, const Floats& hi) {
             const std::vector<Vec3f> a = points(lo, "BoxTree: min"),
                                      b = points(hi, "BoxTree: max");
             if (a.size() != b.size()) throw Error("BoxTree: min and max differ in count");
             BoxStream boxes;
             for (std::size_t i = 0; i < a.size(); ++i) boxes.push(Aabb{a[i], b[i]});
             return std::make_shared<Bvh>(boxes);
           }),
           py::arg("min"), py::arg("max"))
      .def(
          "query",
          [](const Bvh& tree, const Floats& lo, const Floats& hi) {
            const std::vector<Vec3f> a = points(lo, "BoxTree.query: min"),
                                     b = points(hi, "BoxTree.query: max");
            if (a.size() != b.size()) throw Error("BoxTree.query: min and max differ in count");
            std::vector<std::uint32_t> pairs, found;
            for (std::size_t q = 0; q < a.size(); ++q) {
              found.clear();
              tree.query(Aabb{a[q], b[q]}, found);
              for (std::uint32_t id : found) pairs.push_back(std::uint32_t(q)), pairs.push_back(id);
            }
            py::array_t<std::uint32_t> out({py::ssize_t(pairs.size() / 2), py::ssize_t(2)});
            std::copy(pairs.begin(), pairs.end(), out.mutable_data());
            return out;
          },
          py::arg("min"), py::arg("max"),
          "The (query, box) pairs that overlap (closed boxes), as a (k, 2) array");
}

}  // namespace

PYBIND11_MODULE(simdphys, m) {
  m.doc() = "simdphys: data-oriented SIMD physics (docs/python.md)";
  static py::exception<Error> error(m, "Error", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      error(e.what());
    }
  });
  m.def("available_paths", &availablePaths, "Execution paths of this CPU, best first");
  m.def("active_path", &activePath);
  m.def(
      "set_path", [](const std::string& p) { setPath(p); }, py::arg("path"));
  bindWorld(m);
  bindScene(m);
  bindQueries(m);
  bindBatch(m);
}
