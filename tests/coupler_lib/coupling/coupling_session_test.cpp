// The coupling session of a program that runs alone (a replay): no agreement, no checkpoints,
// a local instability ends the run at once. Both sides together, live, are tested by the
// session_pair MPMD driver (drivers/session_pair.cpp).
#include "coupler_lib/coupling/coupling_session.hpp"
#include "coupler_lib/coupling/run_summary.hpp"

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace lbdem {
namespace {

struct Alone : ::testing::Test {
  Alone() {
    side.side = "fluid";
    side.program = "fluid_app";
    side.log =
        std::make_shared<spdlog::logger>("test", std::make_shared<spdlog::sinks::null_sink_mt>());
    side.side_comm = MPI_COMM_SELF;
    dir = std::filesystem::temp_directory_path() / "lbdem_session_test";
    std::filesystem::create_directories(dir);
    scene.file = (dir / "alone.yaml").string();
    scene.name = "alone";
    schedule.dt = 0.5;
    schedule.steps = 6;
    schedule.checkpoint_interval = 2;
    schedule.output_interval = 3;
  }
  std::filesystem::path dir;
  SideInfo side;
  Scene scene;
  Schedule schedule;
};

TEST_F(Alone, RunsEveryStepAndNeverCheckpoints) {
  CouplingSession session(side, scene, schedule, nullptr);
  EXPECT_FALSE(session.agrees());
  int checkpoints = 0, accepted = 0;
  session.on_checkpoint([&](const std::string&, const CheckpointHeader&) { ++checkpoints; });
  std::vector<std::int64_t> labels;
  while (session.ongoing()) {
    labels.push_back(session.next_step());
    EXPECT_FALSE(session.checkpoint_at(session.next_step()));
    session.advance(0, [&] { ++accepted; });
  }
  EXPECT_EQ(labels, (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(accepted, 6);
  EXPECT_EQ(checkpoints, 0);
  EXPECT_EQ(session.end(), SessionEnd::completed);
  EXPECT_EQ(session.finish({}), 0);
  EXPECT_DOUBLE_EQ(session.time_of(session.step()), 3.0);
  EXPECT_TRUE(session.output_at(3));
  // The schedule's agreement steps (checkpoint steps and the last step here), alone as live.
  EXPECT_TRUE(session.agreement_at(4));
  EXPECT_TRUE(session.agreement_at(6));
  EXPECT_FALSE(session.agreement_at(5));
  EXPECT_FALSE(session.output_at(4));
}

TEST_F(Alone, LocalInstabilityEndsAtOnceWithoutAcceptingTheStep) {
  CouplingSession session(side, scene, schedule, nullptr);
  int accepted = 0;
  while (session.ongoing())
    session.advance(session.next_step() == 3 ? kFluidUnstable : 0, [&] { ++accepted; });
  EXPECT_EQ(session.step(), 3);
  EXPECT_EQ(accepted, 2);
  EXPECT_EQ(session.end(), SessionEnd::unstable);
  EXPECT_EQ(session.agreed_flags(), kFluidUnstable);
  EXPECT_EQ(session.finish({}), kExitUnstable);
}

TEST_F(Alone, ResumeContinuesAfterTheCheckpointStep) {
  CouplingSession session(side, scene, schedule, nullptr);
  session.resume("out/run_step0000000004", 4);
  EXPECT_EQ(session.last_checkpoint(), "out/run_step0000000004");
  std::vector<std::int64_t> labels;
  while (session.ongoing()) {
    labels.push_back(session.next_step());
    session.advance(0);
  }
  EXPECT_EQ(labels, (std::vector<std::int64_t>{5, 6}));
  EXPECT_EQ(session.header(6).step, 6);
  EXPECT_DOUBLE_EQ(session.header(6).time, 3.0);
  EXPECT_EQ(session.header(6).side, "fluid");
}

TEST_F(Alone, WritesTheRunSummaryWithCountersAndTheSplit) {
  CouplingSession session(side, scene, schedule, nullptr);
  session.count("cells", 4096);
  session.count("bodies", 3);
  session.count("bodies", 5);  // set, not added
  session.output("out/trace.csv");
  while (session.ongoing()) session.timed("lattice", [&] { session.advance(0); });
  CouplingTimes coupler;  // 6 steps: 100 bytes in 2 messages per step
  coupler.bytes = 600;
  coupler.messages = 12;
  EXPECT_EQ(session.finish(coupler), 0);
  std::ifstream in(run_summary_path(scene, "fluid"));
  ASSERT_TRUE(in) << run_summary_path(scene, "fluid");
  std::stringstream text;
  text << in.rdbuf();
  const std::string json = text.str();
  for (const char* want :
       {"\"end\": \"completed\"", "\"steps\": {\"first\": 0, \"last\": 6, \"schedule\": 6}",
        "\"cells\": {\"values\": [4096]", "\"bodies\": {\"values\": [5]", "\"max_rss_mib\"",
        "\"coupler_bytes_per_step\": {\"values\": [100]", "\"busy_cpu_s_per_step\"",
        "\"per_step_cpu_s\": {\"lattice\": ", "\"coupler_messages_per_step\": {\"values\": [2]",
        "\"lattice\": ", "\"idle\": 0", "\"outputs\": [\"out/trace.csv\"]", "\"max_over_mean\": 1"})
    EXPECT_NE(json.find(want), std::string::npos) << want << "\n" << json;
}

TEST_F(Alone, TheWaitBeforeTheFirstStepIsNotPartOfTheSplit) {
  CouplingSession session(side, scene, schedule, nullptr);
  CouplingTimes start;  // the first exchange: 4 s waiting for the other program's set-up
  start.calls = 1;
  start.total_s = 4.5;
  start.idle_s = 4.0;
  start.bytes = 1000;
  start.messages = 1;
  session.steps_begin(start);
  while (session.ongoing()) session.advance(0);
  CouplingTimes coupler = start;  // then 6 steps: 0.75 s in the coupler, 0.375 s of it waiting
  coupler.calls += 12;
  coupler.total_s += 0.75;
  coupler.idle_s += 0.375;
  coupler.bytes += 600;
  coupler.messages += 12;
  EXPECT_EQ(session.finish(coupler), 0);
  std::ifstream in(run_summary_path(scene, "fluid"));
  std::stringstream text;
  text << in.rdbuf();
  const std::string json = text.str();
  for (const char* want : {"\"before_steps_s\": 4.5", "\"exchange\": 0.0625", "\"idle\": 0.0625",
                           "\"coupler_bytes_per_step\": {\"values\": [100]"})
    EXPECT_NE(json.find(want), std::string::npos) << want << "\n" << json;
}

TEST(RunSummary, MaxOverMeanIsTheLoadImbalance) {
  EXPECT_DOUBLE_EQ(max_over_mean({1.0, 1.0, 2.0, 0.0}), 2.0);
  EXPECT_DOUBLE_EQ(max_over_mean({}), 1.0);
  EXPECT_DOUBLE_EQ(max_over_mean({0.0, 0.0}), 1.0);
}

TEST_F(Alone, TimedReturnsTheValueAndAddsUpParts) {
  CouplingSession session(side, scene, schedule, nullptr);
  EXPECT_EQ(session.timed("lattice", [] { return 42; }), 42);
  session.timed("lattice", [] {});
  session.add_time("bodies", 1.5);
  session.describe("bodies", "2 substeps");
  while (session.ongoing()) session.advance(0);
  CouplingTimes coupler;
  coupler.total_s = 0.9;
  coupler.idle_s = 0.6;
  const std::string line = session.step_split(coupler);
  EXPECT_NE(line.find("time per coupled step (fluid rank 0): lattice "), std::string::npos) << line;
  EXPECT_NE(line.find(", bodies 2.500e-01 s (2 substeps), exchange 5.000e-02 s, idle (waiting for "
                      "the recording) 1.000e-01 s"),
            std::string::npos)
      << line;
}

}  // namespace
}  // namespace lbdem
