// Snapshots (snapshot.hpp): a restored world steps bit for bit as the original does, its handles
// still name its elements, and damaged snapshots are refused, saying how.
#include "simdphys/snapshot.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "simdphys/scene_file.hpp"

namespace simdphys {
namespace {

const std::filesystem::path kScenes = SIMDPHYS_SOURCE_DIR "/scenes";

std::string errorOf(std::span<const std::byte> bytes) {
  try {
    restore(bytes);
  } catch (const Error& e) {
    return e.what();
  }
  return "(restored without an error)";
}

// A snapshot holds every member a step reads, so two worlds in the same state give the same
// bytes: the strongest comparison there is, and it covers the contact caches and sleep state
// that no public accessor shows.
void expectSameState(const World& a, const World& b) {
  const std::vector<std::byte> sa = snapshot(a), sb = snapshot(b);
  ASSERT_EQ(sa.size(), sb.size());
  EXPECT_EQ(std::memcmp(sa.data(), sb.data(), sa.size()), 0);
}

TEST(Snapshot, ARestoredPlaygroundStepsBitForBitAsTheOriginal) {
  // Every section: obstacles with a mesh, particles, a grid and a network cloth, bodies with warm
  // contacts, a kinematic body and sleeping on.
  SceneFile scene = loadScene(kScenes / "playground.json");
  World& original = scene.world;
  for (int frame = 0; frame < 20; ++frame) original.step();
  World restored = restore(snapshot(original));
  expectSameState(original, restored);
  for (int frame = 0; frame < 20; ++frame) original.step(), restored.step();
  expectSameState(original, restored);
  // The streams themselves, read through the public API, agree too.
  const RigidBodies &a = original.bodies(), &b = restored.bodies();
  for (const Handle h : scene.bodies) {
    ASSERT_EQ(a.position(h), b.position(h));
    ASSERT_EQ(a.orientation(h).coeffs(), b.orientation(h).coeffs());
    ASSERT_EQ(a.asleep(h), b.asleep(h));
  }
  const Cloth &ca = original.cloth(scene.cloths[0]), &cb = restored.cloth(scene.cloths[0]);
  for (std::uint32_t i = 0; i < ca.size(); ++i) ASSERT_EQ(ca.position(i), cb.position(i));
}

TEST(Snapshot, APyramidSavedToAFileAndLoadedStepsTheSame) {
  SceneFile scene = loadScene(kScenes / "w5_pyramid_b10.json");
  for (int frame = 0; frame < 5; ++frame) scene.world.step();
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("simdphys_snapshot_" + std::to_string(::getpid()) + ".bin");
  saveSnapshot(scene.world, file);
  World loaded = loadSnapshot(file);
  std::filesystem::remove(file);
  EXPECT_EQ(loaded.bodies().manifoldCount(), scene.world.bodies().manifoldCount());
  for (int frame = 0; frame < 10; ++frame) scene.world.step(), loaded.step();
  expectSameState(scene.world, loaded);
}

TEST(Snapshot, DamagedSnapshotsAreRefusedSayingHow) {
  SceneFile scene = loadScene(kScenes / "playground.json");
  scene.world.step();
  const std::vector<std::byte> good = snapshot(scene.world);
  const std::span<const std::byte> all(good);
  EXPECT_EQ(errorOf(all.first(10)),
            "restore: not a simdphys snapshot (no \"SIMDPHYS-SNAPSHOT\" header)");
  EXPECT_EQ(errorOf({}), "restore: not a simdphys snapshot (no \"SIMDPHYS-SNAPSHOT\" header)");
  EXPECT_EQ(errorOf(all.first(all.size() - 1)).rfind("restore: the snapshot is truncated: ", 0),
            0u);
  EXPECT_EQ(errorOf(all.first(all.size() / 2)).rfind("restore: the snapshot is truncated: ", 0),
            0u);
  std::vector<std::byte> longer = good;
  longer.push_back(std::byte{0});
  EXPECT_EQ(errorOf(longer), "restore: the snapshot has 1 bytes after its data");
  // One bit flipped anywhere in the data: the checksum differs.
  for (const std::size_t at : {std::size_t(40), good.size() / 3, good.size() - 1}) {
    std::vector<std::byte> bad = good;
    bad[at] ^= std::byte{0x10};
    EXPECT_EQ(errorOf(bad), "restore: the snapshot is corrupt (its checksum differs)") << at;
  }
  std::vector<std::byte> later = good;
  later[18] = std::byte{kSnapshotVersion + 1};  // the version, right after the 18-byte magic
  EXPECT_EQ(errorOf(later), "restore: snapshot format version " +
                                std::to_string(kSnapshotVersion + 1) +
                                ", this library reads version " + std::to_string(kSnapshotVersion));
}

TEST(Snapshot, AFileThatIsNoSnapshotIsRefusedNamingIt) {
  const std::filesystem::path scene = kScenes / "playground.json";
  try {
    loadSnapshot(scene);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(
        std::string(e.what()),
        scene.string() + ": restore: not a simdphys snapshot (no \"SIMDPHYS-SNAPSHOT\" header)");
  }
  EXPECT_THROW(loadSnapshot(kScenes / "absent.bin"), Error);
}

}  // namespace
}  // namespace simdphys
