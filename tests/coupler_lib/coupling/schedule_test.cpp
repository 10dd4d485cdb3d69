#include <gtest/gtest.h>

#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/coupling/stop_request.hpp"

namespace lbdem {
namespace {

Scene coupled(const std::string& coupling = "") {
  const std::string text = R"(
time: {end: 1.0}
fluid: {domain: [1, 1, 1], dx: 0.1, viscosity: 0.01, tau: 0.8}
dem: {dt: 0.003, periodic: xyz}
shapes: [{name: b, kind: sphere, diameter: 0.2}]
bodies: [{shape: b, position: [0.5, 0.5, 0.5], density: 2000}]
)" + coupling;
  return parse_scene(Section::load_string(text, "s.yaml"), 0);
}

TEST(Schedule, SubstepsRoundUpSoTheDemStepNeverGrows) {
  EXPECT_EQ(dem_substeps(0.01, 0.003), 4);  // 3.33 -> 4, dt_DEM = 0.0025 <= 0.003
  EXPECT_EQ(dem_substeps(0.01, 0.0025), 4);
  EXPECT_EQ(dem_substeps(0.01, 0.01 / 3), 3);  // ratio 3.0000000000000004 is still 3
  EXPECT_EQ(dem_substeps(1.0, 0.1), 10);       // 1.0 / 0.1 = 10 in floating point
}

TEST(Schedule, DemStepLargerThanFluidStepUsesTheFluidStep) {
  EXPECT_EQ(dem_substeps(0.01, 0.02), 1);
  const Schedule s = make_schedule(coupled(), 0.01, 0.02);
  EXPECT_EQ(s.dem_substeps, 1);
  EXPECT_DOUBLE_EQ(s.dt_dem, 0.01);
}

TEST(Schedule, StepsCadenceAndExchange) {
  // The reader refuses these two cadences for now (see CouplingKeysAreCheckedByTheReader); the
  // schedule itself already handles them.
  Scene scene = coupled("coupling: {output_interval: 0.1}\n");
  scene.coupling.exchange_interval = 2;
  scene.coupling.checkpoint_interval = 0.25;
  const Schedule s = make_schedule(scene, 0.01, 0.003);
  EXPECT_EQ(s.steps, 100);
  EXPECT_EQ(s.dem_substeps, 4);
  EXPECT_DOUBLE_EQ(s.dt_dem, 0.0025);
  EXPECT_EQ(s.exchange_interval, 2);
  EXPECT_EQ(s.output_interval, 10);
  EXPECT_EQ(s.checkpoint_interval, 26);  // 12.5 exchanges round to 13, on exchange steps
  EXPECT_TRUE(s.exchange_at(4));
  EXPECT_FALSE(s.exchange_at(5));
  EXPECT_TRUE(s.output_at(20));
  EXPECT_FALSE(s.checkpoint_at(25));
}

TEST(Schedule, InRunRebalancingStepsAreAgreementSteps) {
  Scene scene = coupled();
  EXPECT_EQ(make_schedule(scene, 0.01, 0.003).rebalance_interval, 0);  // none by default
  scene.fluid->decomposition = DecompositionKind::balanced;
  scene.fluid->rebalance_interval = 0.05;
  const Schedule s = make_schedule(scene, 0.01, 0.003);
  EXPECT_EQ(s.rebalance_interval, 5);
  EXPECT_TRUE(s.rebalance_at(10));
  EXPECT_FALSE(s.rebalance_at(12));
  // Both programs meet there: an overlapped fluid waits for the states of that step.
  EXPECT_TRUE(agreement_at(scene, s, 10));
  scene.fluid->output.stability.interval = 0;
  EXPECT_FALSE(agreement_at(scene, s, 12));
}

TEST(Schedule, NoCadenceByDefaultAndEndRoundsUp) {
  const Schedule s = make_schedule(coupled(), 0.3, 0.003);
  EXPECT_EQ(s.steps, 4);  // 3.33 fluid steps to reach 1 s
  EXPECT_EQ(s.output_interval, 0);
  EXPECT_FALSE(s.output_at(0));
  EXPECT_FALSE(s.checkpoint_at(4));
}

// Awkward end / dt pairs whose quotient lands a rounding error above or below a whole number:
// both programs count with step_count, so they agree; the count is the exact ceiling.
TEST(Schedule, StepCountOnAwkwardEndAndStep) {
  EXPECT_EQ(step_count(0.3, 0.1), 3);  // 2.9999999999999996
  EXPECT_EQ(step_count(0.7, 0.1), 7);  // 6.999999999999999
  EXPECT_EQ(step_count(1.0, 0.1), 10);
  EXPECT_EQ(step_count(0.6, 0.2), 3);     // 2.9999999999999996
  EXPECT_EQ(step_count(1.1, 0.1), 11);    // 11.000000000000002
  EXPECT_EQ(step_count(1e-3, 1e-4), 10);  // 10.000000000000002
  EXPECT_EQ(step_count(0.35, 0.1), 4);    // a real fraction rounds up
  EXPECT_EQ(step_count(0.01, 1.0), 1);    // end shorter than one step: one step
  for (int n = 1; n <= 2000; ++n) {
    const double dt = 1.0 / 3.0e4;
    EXPECT_EQ(step_count(n * dt, dt), n) << n;
    EXPECT_EQ(step_count(n * 0.1, 0.1), n) << n;
  }
  // make_schedule counts with the same function.
  EXPECT_EQ(make_schedule(coupled(), 0.1, 0.003).steps, step_count(1.0, 0.1));
}

TEST(Schedule, RejectsMissingSteps) {
  EXPECT_THROW(make_schedule(coupled(), 0.0, 0.003), SceneError);
  EXPECT_THROW(make_schedule(coupled(), 0.01, -1.0), SceneError);
}

TEST(Schedule, CouplingKeysAreCheckedByTheReader) {
  EXPECT_THROW(coupled("coupling: {exchange_interval: 0}\n"), SceneError);
  EXPECT_THROW(coupled("coupling: {exchange_interval: 2}\n"), SceneError);
  EXPECT_EQ(coupled("coupling: {checkpoint_interval: 1.0}\n").coupling.checkpoint_interval, 1.0);
  EXPECT_EQ(
      coupled("coupling: {checkpoint_interval: 1.0, overlap: true}\n").coupling.checkpoint_interval,
      1.0);
  EXPECT_EQ(coupled("coupling: {exchange_interval: 1, checkpoint_interval: 0}\n")
                .coupling.exchange_interval,
            1);
  EXPECT_THROW(coupled("coupling: {wait: spin}\n"), SceneError);
  EXPECT_EQ(coupled("coupling: {wait: blocking}\n").coupling.wait, WaitMode::blocking);
  EXPECT_TRUE(coupled().coupling.overlap);  // the default: measured, docs/coupling-overlap.md
  EXPECT_FALSE(coupled("coupling: {overlap: false}\n").coupling.overlap);
  EXPECT_THROW(coupled("coupling: {overlap: 2}\n"), SceneError);
  EXPECT_THROW(coupled("coupling: {overlap: sometimes}\n"), SceneError);
}

}  // namespace
}  // namespace lbdem
