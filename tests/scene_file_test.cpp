// Scene files (scene_file.hpp): the standard workloads' files build the worlds the benchmarks
// build, bit for bit; a playground of every section loads and steps; and every malformed file of
// tests/scene_files/ is refused with an error naming the file, the JSON place and the problem.
#include "simdphys/scene_file.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include <unistd.h>

#include "simdphys/measures.hpp"
#include "workloads/cloth.hpp"
#include "workloads/particles.hpp"
#include "workloads/pyramid.hpp"

namespace simdphys {
namespace {

const std::filesystem::path kScenes = SIMDPHYS_SOURCE_DIR "/scenes";
const std::filesystem::path kCorpus = SIMDPHYS_SOURCE_DIR "/tests/scene_files";

// Bitwise equality of two float spans (NaN-safe, -0 != +0): the loaded world must be the one the
// benchmark builds, not a close one.
void expectSameBits(std::span<const float> a, std::span<const float> b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0) << what;
}

template <class Set>
void expectSameStreams(const Set& a, const Set& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t f = 0; f < Set::Layout::kCount; ++f)
    expectSameBits(a.field(f).view(), b.field(f).view(), ("field " + std::to_string(f)).c_str());
}

void expectSameSettings(const WorldSettings& a, const WorldSettings& b) {
  EXPECT_EQ(std::bit_cast<std::uint32_t>(a.timeStep), std::bit_cast<std::uint32_t>(b.timeStep));
  EXPECT_EQ(a.substeps, b.substeps);
  EXPECT_EQ(a.threads, b.threads);
}

void expectSameObb(const Obb& a, const Obb& b) {
  EXPECT_EQ(a.center, b.center);
  EXPECT_EQ(a.halfExtents, b.halfExtents);
  EXPECT_EQ(a.axes, b.axes);
}

TEST(SceneFile, PyramidFilesBuildW5AsTheBenchmarkDoesAndStepTheSame) {
  for (const int base : workloads::kPyramidBases) {
    SceneFile scene = loadScene(kScenes / ("w5_pyramid_b" + std::to_string(base) + ".json"));
    EXPECT_EQ(scene.frames, workloads::kPyramidFrames);
    // W5 as bench/rigid_bench.cpp and examples/pyramid build it.
    World w(WorldSettings{workloads::kPyramidFrameTime, 1, 1});
    RigidSettings settings;
    settings.sleeping = false;
    w.bodies().setSettings(settings);
    w.obstacles().add(workloads::kPyramidGround);
    for (const Vec3f& p : workloads::pyramidCenters(base)) {
      BodyDef d;
      d.position = p, d.friction = workloads::kPyramidFriction;
      w.bodies().add(d);
    }
    expectSameSettings(scene.world.settings(), w.settings());
    EXPECT_FALSE(scene.world.bodies().settings().sleeping);
    ASSERT_EQ(scene.world.obstacles().size(), 1u);
    expectSameObb(std::get<Obb>(scene.world.obstacles().shapes()[0]), workloads::kPyramidGround);
    expectSameStreams(scene.world.bodies(), w.bodies());
    EXPECT_EQ(scene.bodies.size(), workloads::pyramidBoxCount(base));
    if (base > workloads::kPyramidBases[0]) continue;  // stepping one size shows it
    for (int frame = 0; frame < 3; ++frame) scene.world.step(), w.step();
    expectSameStreams(scene.world.bodies(), w.bodies());
  }
}

TEST(SceneFile, ParticleFileBuildsW4AsTheBenchmarkDoesAndStepsTheSame) {
  SceneFile scene = loadScene(kScenes / "w4_particles.json");
  workloads::ParticleWorkload w = workloads::makeParticleWorkload();
  EXPECT_EQ(scene.frames, workloads::kParticleFrames);
  expectSameSettings(scene.world.settings(), w.world.settings());
  ASSERT_EQ(scene.world.obstacles().size(), 2u);
  // The ramp's axes from {"axis": [0, 0, 1], "angle": 0.35} equal rotationZ(0.35)'s, rounded once.
  expectSameObb(std::get<Obb>(scene.world.obstacles().shapes()[0]), workloads::particleGround());
  expectSameObb(std::get<Obb>(scene.world.obstacles().shapes()[1]), workloads::particleRamp());
  ASSERT_EQ(scene.particleSystems.size(), 1u);
  const ParticleSystem& a = scene.world.particles(scene.particleSystems[0]);
  const ParticleSystem& b = w.world.particles(w.particles);
  const ParticleSettings &sa = a.settings(), &sb = b.settings();
  EXPECT_EQ(sa.integrator, sb.integrator);
  EXPECT_EQ(sa.gravity, sb.gravity);
  EXPECT_EQ(sa.restitution, sb.restitution);
  EXPECT_EQ(sa.damping, sb.damping);
  EXPECT_EQ(sa.friction, sb.friction);
  expectSameStreams(a, b);
  for (int frame = 0; frame < 2; ++frame) scene.world.step(), w.world.step();
  expectSameStreams(a, b);
}

TEST(SceneFile, ClothFileBuildsW3AsTheBenchmarkDoesAndStepsTheSame) {
  SceneFile scene = loadScene(kScenes / "w3_cloth.json");
  EXPECT_EQ(scene.frames, workloads::kClothFrames);
  World w(WorldSettings{workloads::kClothFrameTime, 1, 1});
  w.obstacles().add(workloads::kClothSphere);
  const Handle cloth =
      w.addCloth(Cloth::grid(workloads::clothGrid(workloads::makeClothWorkload(128))));
  expectSameSettings(scene.world.settings(), w.settings());
  ASSERT_EQ(scene.world.obstacles().size(), 1u);
  const Sphere s = std::get<Sphere>(scene.world.obstacles().shapes()[0]);
  EXPECT_EQ(s.center, workloads::kClothSphere.center);
  EXPECT_EQ(s.radius, workloads::kClothSphere.radius);
  ASSERT_EQ(scene.cloths.size(), 1u);
  const Cloth &a = scene.world.cloth(scene.cloths[0]), &b = w.cloth(cloth);
  ASSERT_EQ(a.springs().size(), b.springs().size());
  for (std::size_t i = 0; i < a.springs().size(); ++i) {
    const Spring &p = a.springs()[i], &q = b.springs()[i];
    ASSERT_TRUE(p.a == q.a && p.b == q.b && p.rest == q.rest && p.stiffness == q.stiffness)
        << "spring " << i;
  }
  for (int frame = 0; frame <= 2; ++frame) {
    if (frame > 0) scene.world.step(), w.step();
    for (std::uint32_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a.position(i), b.position(i)) << "particle " << i << ", frame " << frame;
      ASSERT_EQ(a.invMass(i), b.invMass(i)) << "particle " << i;
    }
  }
}

TEST(SceneFile, PlaygroundHoldsEverySectionAndStepsFinite) {
  SceneFile scene = loadScene(kScenes / "playground.json");
  EXPECT_EQ(scene.name, "playground");
  EXPECT_EQ(scene.obstacles.size(), 5u);
  ASSERT_EQ(scene.particleSystems.size(), 1u);
  EXPECT_EQ(scene.world.particles(scene.particleSystems[0]).size(), 2001u);  // 1 + the emitter's
  ASSERT_EQ(scene.cloths.size(), 2u);
  EXPECT_TRUE(scene.world.cloth(scene.cloths[0]).isGrid());
  EXPECT_EQ(scene.world.cloth(scene.cloths[1]).springs().size(), 4u);
  EXPECT_EQ(scene.bodies.size(), 6u + 30u);  // the 6 bodies, then the pyramid's 16 + 9 + 4 + 1
  const RigidBodies& bodies = scene.world.bodies();
  EXPECT_TRUE(bodies.kinematic(scene.bodies[5]));
  // The wedge: 6 points, 5 faces (two triangles, three rectangles); the gem's 8 points all
  // vertices.
  EXPECT_EQ(bodies.hull(scene.bodies[3])->faceCount(), 5);
  EXPECT_EQ(bodies.hull(scene.bodies[4])->vertices().size(), 8u);
  // The quaternion given as (x, y, z, w): a turn of 45 degrees about +y.
  const Quatf q = bodies.orientation(scene.bodies[2]);
  EXPECT_NEAR(q.y(), 0.3826834f, 1e-6f);  // the file's value, normalised (|q| was 1 to 1e-7)
  EXPECT_NEAR(q.w(), 0.9238795f, 1e-6f);
  for (int frame = 0; frame < 30; ++frame) scene.world.step();
  for (std::size_t f = 0; f < fields::Body::kCount; ++f)
    for (const float v : bodies.stream(f)) ASSERT_TRUE(std::isfinite(v)) << "body field " << f;
  for (const Vec3f& p : scene.world.cloth(scene.cloths[0]).positions()) ASSERT_TRUE(p.allFinite());
  const ParticleSystem& particles = scene.world.particles(scene.particleSystems[0]);
  for (std::size_t i = 0; i < particles.size(); ++i)
    ASSERT_GE(particles.y()[i], 0.0f);  // above the plane
}

TEST(SceneFile, EverySceneInScenesLoadsAndSteps) {
  std::size_t scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json") continue;  // batches/ holds batch files
    SceneFile scene = loadScene(entry.path());
    WorldMonitor monitor(scene.world);
    for (int frame = 0; frame < 2; ++frame) scene.world.step(), monitor.observe(scene.world);
    const WorldMeasures m = monitor.measure(scene.world);
    EXPECT_TRUE(m.bodies.finite) << entry.path();
    for (const ClothMeasures& c : m.cloths) EXPECT_TRUE(c.finite) << entry.path();
    for (const ParticleMeasures& p : m.particles) EXPECT_TRUE(p.finite) << entry.path();
    EXPECT_GT(scene.frames, 0) << entry.path();
    ++scenes;
  }
  EXPECT_EQ(scenes, 5u);  // W3, W4, W5 at two sizes, the playground
}

// Every file of tests/scene_files/ and the message it must give after "<its path>: ".
const std::map<std::string, std::string> kExpected{
    {"empty", "the file is empty"},
    {"whitespace_only", "the file is empty"},
    {"not_json", "not valid JSON: parse error at line 1"},
    {"nan_literal", "not valid JSON: parse error at line 1"},
    {"nan_string", "/settings/timeStep: must be a number, got the string \"NaN\""},
    {"infinity_string",
     "/rigid/bodies/0/position/0: must be a number, got the string \"Infinity\""},
    {"truncated", "not valid JSON: parse error at line 2"},
    {"top_level_array", "/: must be an object, got an array"},
    {"missing_version", "/: missing field \"simdphys\""},
    {"wrong_version", "/simdphys: format version 2 is not one this library reads (1)"},
    {"version_as_string", "/simdphys: must be a number, got the string \"1\""},
    {"unknown_top_level_key", "/bodies: unknown field (known here: simdphys, name,"},
    {"unknown_body_key", "/rigid/bodies/0/halfExtent: unknown field"},
    {"negative_half_extent", "/rigid/bodies/17/halfExtents/1: must be positive, got -0.5"},
    {"zero_mass", "/rigid/bodies/0/mass: must be positive, got 0"},
    {"hull_of_flat_points", "/rigid/bodies/0/points: the points are flat"},
    {"points_on_a_box", "/rigid/bodies/0/points: only a hull has points"},
    {"negative_time_step", "/settings: timeStep is -0.01, must be in (0, 1] s"},
    {"zero_rigid_substeps", "/rigid/settings: substeps is 0, must be in [1, 64]"},
    {"friction_as_word", "/rigid/bodies/0/friction: must be a number, got the string \"high\""},
    {"position_of_two", "/rigid/bodies/0/position: must be an array of 3 numbers, got 2"},
    {"position_as_object", "/rigid/bodies/0/position: must be an array, got an object"},
    {"unknown_obstacle_type",
     "/obstacles/0/type: \"cylinder\" is not one of plane, sphere, aabb, box, mesh"},
    {"obstacle_without_type", "/obstacles/0: missing field \"type\""},
    {"missing_obj_file", "/obstacles/0/obj: "},
    {"zero_plane_normal", "/obstacles/0/normal: must not be zero"},
    {"inverted_aabb", "/obstacles/0/max: must be >= min on every axis"},
    {"negative_radius", "/obstacles/0/radius: must be positive, got -1"},
    {"huge_emitter_count",
     "/particles/0/emitters/0/count: must be in [0, 100000000], got 1000000000000"},
    {"fractional_count", "/particles/0/emitters/0/count: must be a whole number, got 2.5"},
    {"unknown_integrator",
     "/particles/0/settings/integrator: \"rk4\" is not one of explicitEuler, semiImplicitEuler, "
     "velocityVerlet, positionVerlet"},
    {"restitution_above_one", "/particles/0/settings: restitution is 1.5, must be in [0, 1]"},
    {"cloth_grid_of_one", "/cloths/0/grid/nx: must be in [2, 10000], got 1"},
    {"cloth_pin_outside", "/cloths/0/grid/pinned/0/0: must be in [0, 3], got 128"},
    {"spring_to_itself", "/cloths/0/springs/0/b: joins particle 1 to itself"},
    {"spring_index_outside", "/cloths/0/springs/0/b: must be in [0, 2], got 7"},
    {"grid_and_springs", "/cloths/0: give either a grid or particles and springs"},
    {"zero_rotation_axis", "/obstacles/0/rotation/axis: must not be zero"},
    {"quaternion_of_three",
     "/rigid/bodies/0/rotation/quaternion: must be an array of 4 numbers (x, y, z, w)"},
    {"pyramid_of_spheres", "/rigid/pyramids/0/body: a pyramid is built of boxes"},
    {"coordinate_too_large", "/rigid/bodies/0/position/0: must be in [-1e+18, 1e+18], got 1e+30"},
    {"unknown_contact_model",
     "/rigid/settings/model: \"pgs\" is not one of softStep, baumgarte, projection"},
    {"negative_threads", "/settings: threads is -1, must be >= 0"},
    {"negative_frames", "/settings/frames: must be in [0, 100000000], got -5"},
    {"negative_stiffness", "/cloths/0/grid/structural/stiffness: must be positive, got -1"},
    {"binary_garbage", "not valid JSON: parse error at line 1"},
    {"deep_nesting", "/: must be an object, got an array"},
    {"null_settings", "/settings: must be an object, got null"},
    {"boolean_as_number", "/rigid/settings/sleeping: must be true or false, got a number"},
};

std::string errorOf(const std::filesystem::path& file) {
  try {
    loadScene(file);
  } catch (const Error& e) {
    return e.what();
  }
  return "(loaded without an error)";
}

TEST(SceneFile, EveryMalformedFileIsRefusedNamingTheFileThePlaceAndTheProblem) {
  std::size_t seen = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kCorpus)) {
    const std::string name = entry.path().stem().string();
    const auto expected = kExpected.find(name);
    ASSERT_NE(expected, kExpected.end()) << name << ".json has no expected message here";
    const std::string message = errorOf(entry.path());
    const std::string prefix = entry.path().string() + ": ";
    EXPECT_EQ(message.rfind(prefix + expected->second, 0), 0u)
        << name << ": got \"" << message << "\"";
    ++seen;
  }
  EXPECT_EQ(seen, kExpected.size());  // no expected message without its file
  EXPECT_GE(seen, 30u);               // the issue's corpus
}

TEST(SceneFile, MissingOrUnreadableFilesAreRefused) {
  EXPECT_EQ(errorOf(kCorpus / "absent.json")
                .rfind((kCorpus / "absent.json").string() + ": cannot be read (No such file", 0),
            0u);
  EXPECT_EQ(errorOf(kCorpus), kCorpus.string() + ": is a directory, not a scene file");
  EXPECT_NE(errorOf(kCorpus / "missing_obj_file.json").find("nowhere.obj"), std::string::npos);
}

TEST(SceneFile, AHugeFileIsRefusedBeforeItIsRead) {
  // Sparse: a gigabyte that takes no disk, refused by its size alone.
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("simdphys_huge_scene_" + std::to_string(::getpid()) + ".json");
  { std::ofstream(file) << "{"; }
  std::filesystem::resize_file(file, std::uintmax_t(1) << 30);
  EXPECT_EQ(errorOf(file),
            file.string() + ": the file is 1024 MiB, more than the 256 MiB a scene file may be");
  std::filesystem::remove(file);
}

TEST(SceneFile, ParsedTextNamesItsSourceAndBuildsNothingOnAnError) {
  const std::string ok = R"({"simdphys": 1, "rigid": {"bodies": [{"position": [0, 1, 0]}]}})";
  SceneFile scene = parseScene(ok, "inline");
  EXPECT_EQ(scene.world.bodies().size(), 1u);
  EXPECT_EQ(scene.frames, 60);  // the default run
  // The first body is fine, the second is not: the error names it, and no world comes back.
  const std::string bad =
      R"({"simdphys": 1, "rigid": {"bodies": [{"position": [0, 1, 0]}, {"position": [0, 1]}]}})";
  try {
    parseScene(bad, "inline");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "inline: /rigid/bodies/1/position: must be an array of 3 numbers, got 2");
  }
}

}  // namespace
}  // namespace simdphys
