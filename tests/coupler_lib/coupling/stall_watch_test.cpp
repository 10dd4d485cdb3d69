#include "coupler_lib/coupling/stall_watch.hpp"

#include <gtest/gtest.h>

#include <thread>

#include "coupler_lib/coupling/world.hpp"

namespace lbdem {
namespace {

PeerInfo dem_peer() {
  PeerInfo p;
  p.side = "dem";
  p.program = "dem_app";
  return p;
}

TEST(StallWatch, AFixedLimitEndsAWaitWithTheSilentSideAndTheLastStep) {
  StallWatch w(0.05, dem_peer());
  w.begin(4);
  w.end();
  w.begin(5);
  EXPECT_NO_THROW(w.check());
  std::this_thread::sleep_for(std::chrono::milliseconds(80));
  try {
    w.check();
    FAIL() << "no error after the limit";
  } catch (const SideError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("dem_app (the dem side) has sent nothing for"), std::string::npos) << m;
    EXPECT_NE(m.find("coupling.stall_timeout"), std::string::npos) << m;
    EXPECT_NE(m.find("at step 5"), std::string::npos) << m;
    EXPECT_NE(m.find("last completed exchange: step 4"), std::string::npos) << m;
    EXPECT_NE(m.find("last checkpoint: none"), std::string::npos) << m;
  }
}

TEST(StallWatch, TheAutomaticLimitAllowsTheSetUpThenAMinuteAndGrowsWithTheSlowestExchange) {
  StallWatch w(0, dem_peer());
  // The waits of the first two exchanges hold the other program's set-up and first step.
  for (int k = 0; k < StallWatch::kSetUpWaits; ++k) {
    EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kSetUpLimit);
    w.begin(k / 2);
    // A slow set-up (1.3 s here) does not lift the limit of the rest of the run.
    if (k == 2) std::this_thread::sleep_for(std::chrono::milliseconds(1300));
    EXPECT_NO_THROW(w.check());
    w.end();
  }
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kAutomaticFloor);
  w.begin(2);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  w.end();
  // 50 x 20 ms is still below the floor.
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kAutomaticFloor);
  w.begin(3);
  std::this_thread::sleep_for(std::chrono::milliseconds(1300));
  w.end();
  // An exchange of at least 1.3 s: the limit is 50 x that, above the floor.
  EXPECT_GE(w.limit_s(), StallWatch::kAutomaticFactor * 1.3);
  EXPECT_GT(w.limit_s(), StallWatch::kAutomaticFloor);
  w.begin(4);
  EXPECT_NO_THROW(w.check());
}

TEST(StallWatch, PauseStepsAreTheCheckpointAndFieldStepsAndTheWaitsAfterThem) {
  PauseSteps p;
  EXPECT_FALSE(p.held_by(100));
  p.checkpoint_every = 50;
  p.fields_every = 30;
  EXPECT_TRUE(p.at(50));
  EXPECT_TRUE(p.at(90));
  EXPECT_FALSE(p.at(0));  // the set-up has its own allowance
  EXPECT_FALSE(p.at(70));
  EXPECT_TRUE(p.held_by(51));
  EXPECT_TRUE(p.held_by(60));
  EXPECT_FALSE(p.held_by(62));
}

TEST(StallWatch, AWaitAroundACheckpointGetsThePauseAllowanceWithoutLiftingTheStepLimit) {
  StallWatch w(0, dem_peer());
  w.expect_pauses(PauseSteps{10, 0});
  for (int k = 0; k < StallWatch::kSetUpWaits; ++k) {
    w.begin(k / 2);
    w.end();
  }
  w.begin(9);
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kAutomaticFloor);
  w.end();
  // The waits of the checkpoint step and the one after it may hold the other's write.
  w.begin(10);
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kSetUpLimit);
  std::this_thread::sleep_for(std::chrono::milliseconds(1300));
  EXPECT_NO_THROW(w.check());
  w.end();
  w.begin(11);
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kSetUpLimit);
  w.end();
  // The 1.3 s write is not a step: the limit of the following steps is still the floor.
  w.begin(12);
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kAutomaticFloor);
}

TEST(StallWatch, AnAgreementDuringTheSetUpDoesNotUseUpItsAllowance) {
  StallWatch w(0, dem_peer());
  // An agreement after each of the set-up's packet waits but the last.
  for (int k = 0; k + 1 < StallWatch::kSetUpWaits; ++k) {
    w.begin(k / 2);
    w.end();
    w.begin(k / 2, StallWatch::Wait::agreement);
    EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kSetUpLimit);
    w.end();
  }
  // The last packet wait of the set-up still has its allowance, the next one not.
  w.begin(1);
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kSetUpLimit);
  w.end();
  w.begin(2);
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kAutomaticFloor);
}

TEST(StallWatch, TheMessageNamesWhatThisProgramWaitsFor) {
  StallWatch w(0.01, dem_peer());
  w.begin(100, StallWatch::Wait::agreement);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  try {
    w.check();
    FAIL() << "no error after the limit";
  } catch (const SideError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("has sent nothing for"), std::string::npos) << m;
    EXPECT_NE(m.find("waits for the agreement of both programs at step 100"), std::string::npos)
        << m;
  }
}

TEST(StallWatch, CheckStatesTheLimitAndTheCheckpointSize) {
  Scene scene;
  EXPECT_NE(describe_stall_limit(scene).find("600 s for the first two exchanges"),
            std::string::npos);
  EXPECT_NE(describe_stall_limit(scene).find("larger of 60 s and 50 x the slowest exchange"),
            std::string::npos);
  scene.fluid.emplace();
  scene.fluid->cells = {512, 512, 512};
  scene.coupling.checkpoint_interval = 1e-3;
  // 512^3 x 19 x 8 B = 19 GiB.
  EXPECT_NE(describe_stall_limit(scene).find("a fluid checkpoint holds 19 GiB"), std::string::npos)
      << describe_stall_limit(scene);
  scene.coupling.stall_timeout = 3;
  EXPECT_EQ(describe_stall_limit(scene).rfind("stall limit: 3 s (coupling.stall_timeout)", 0), 0u);
}

}  // namespace
}  // namespace lbdem
