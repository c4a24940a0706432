// Many worlds (batch.hpp): batch files expand their sweeps, patches change the scene as the same
// change made by hand does, and a job's result is the same alone and among others on threads.
#include "simdphys/batch.hpp"

#include <gtest/gtest.h>

#include "simdphys/measures.hpp"
#include "simdphys/snapshot.hpp"

namespace simdphys {
namespace {

const std::filesystem::path kSmall = SIMDPHYS_SOURCE_DIR "/tests/batch/small.json";
const std::filesystem::path kScenes = SIMDPHYS_SOURCE_DIR "/scenes";

TEST(Batch, SweepsExpandIntoEveryCombination) {
  const std::vector<BatchJob> jobs = loadBatch(kSmall);
  ASSERT_EQ(jobs.size(), 2u + 4u + 1u);
  EXPECT_EQ(jobs[0].frames, 10);
  ASSERT_EQ(jobs[1].patches.size(), 1u);
  EXPECT_EQ(jobs[1].patches[0].pointer, "/rigid/settings/substeps");
  EXPECT_EQ(jobs[1].patches[0].json, "6");
  // Two axes: the later key (in sorted order) varies fastest.
  ASSERT_EQ(jobs[3].patches.size(), 2u);
  EXPECT_EQ(jobs[3].patches[0].pointer, "/settings/timeStep");
  EXPECT_EQ(jobs[3].patches[0].json, "0.02");
  EXPECT_EQ(jobs[3].patches[1].pointer, "/rigid/settings/iterations");
  EXPECT_EQ(jobs[3].patches[1].json, "1");
  EXPECT_EQ(jobs[6].patches[0].json, R"({"substeps":4})");
}

TEST(Batch, APatchChangesTheSceneAsTheSameChangeByHand) {
  const ScenePatch patch{"/rigid/settings/substeps", "4"};
  SceneFile patched = loadScene(kScenes / "w5_pyramid_b10.json", {&patch, 1});
  SceneFile byHand = loadScene(kScenes / "w5_pyramid_b10.json");
  RigidSettings s = byHand.world.bodies().settings();
  s.substeps = 4;
  byHand.world.bodies().setSettings(s);
  for (int frame = 0; frame < 5; ++frame) patched.world.step(), byHand.world.step();
  EXPECT_EQ(snapshot(patched.world), snapshot(byHand.world));
  // A patch into a place the scene has no parent for is an error naming it.
  const ScenePatch bad{"/rigid/nowhere/substeps", "4"};
  try {
    loadScene(kScenes / "w5_pyramid_b10.json", {&bad, 1});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("patch /rigid/nowhere/substeps: no such place"),
              std::string::npos)
        << e.what();
  }
}

TEST(Batch, EveryJobGivesTheSameResultAloneAndOnTwoThreads) {
  const std::vector<BatchJob> jobs = loadBatch(kSmall);
  const std::vector<BatchResult> together = runBatch(jobs, 2);
  ASSERT_EQ(together.size(), jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const BatchResult alone = runJob(jobs[i], i);
    EXPECT_EQ(together[i].job, i);
    EXPECT_FALSE(together[i].failed) << together[i].error;
    EXPECT_EQ(together[i].stateHash, alone.stateHash) << "job " << i;
    EXPECT_EQ(together[i].maxDisplacement, alone.maxDisplacement) << "job " << i;
  }
  // Different settings give different states (the hash tells them apart).
  EXPECT_NE(together[0].stateHash, together[1].stateHash);
}

TEST(Batch, AFailingJobIsRecordedAndTheOthersRun) {
  std::vector<BatchJob> jobs = loadBatch(kSmall);
  jobs.resize(2);
  jobs[0].patches = {{"/rigid/settings/substeps", "0"}};
  const std::vector<BatchResult> results = runBatch(jobs, 2);
  EXPECT_TRUE(results[0].failed);
  EXPECT_NE(std::string(results[0].error).find("/rigid/settings: substeps is 0"), std::string::npos)
      << results[0].error;
  EXPECT_FALSE(results[1].failed);
  EXPECT_NE(results[1].stateHash, 0u);
}

}  // namespace
}  // namespace simdphys
