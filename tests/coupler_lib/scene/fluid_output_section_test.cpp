#include <gtest/gtest.h>

#include "coupler_lib/scene/fluid_output_section.hpp"

namespace lbdem {
namespace {

// dt = (0.8 - 0.5) * 0.01^2 / (3 * 1e-2) = 1e-3 s
const UnitConverter kUnits = UnitConverter::from_tau(0.01, 0.8, 1e-2, 1000.0);
const std::array<int, 3> kCells{10, 20, 30};

FluidOutputParams parse(const std::string& fluid_yaml) {
  Section root = Section::load_string("fluid:\n" + fluid_yaml, "o.yaml");
  Section fluid = root.section("fluid");
  FluidOutputParams p = parse_fluid_output(fluid, kUnits, kCells);
  fluid.finish();
  return p;
}

std::string error_of(const std::string& fluid_yaml) {
  try {
    parse(fluid_yaml);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputScene, NoOutputSectionMeansNoFilesButTheWatchIsOn) {
  const FluidOutputParams p = parse("  {}\n");
  EXPECT_FALSE(p.writes_files());
  EXPECT_FALSE(p.fields);
  EXPECT_FALSE(p.series);
  EXPECT_FALSE(p.validation);
  EXPECT_EQ(p.stability.interval, 100);
  EXPECT_DOUBLE_EQ(p.stability.max_mach, 0.3);
}

TEST(OutputScene, IntervalsBecomeStepsAndSlicesNodeIndices) {
  const FluidOutputParams p = parse(R"(  output:
    directory: out
    fields:
      interval: 0.0504
      pressure: true
      stride: 2
      slices:
        - {axis: y, position: 0.0549}
        - {axis: z, position: 0.3}
    series: {interval: 0.0001}
  stability: {interval: 7, max_mach: 0.2, last_good: lg.h5}
)");
  ASSERT_TRUE(p.fields);
  EXPECT_EQ(p.directory, "out");
  EXPECT_EQ(p.fields->every, 50);
  EXPECT_TRUE(p.fields->velocity);
  EXPECT_FALSE(p.fields->density);
  EXPECT_TRUE(p.fields->pressure);
  EXPECT_FALSE(p.fields->volume);  // slices given, volume not asked for
  ASSERT_EQ(p.fields->slices.size(), 2u);
  EXPECT_EQ(p.fields->slices[0].axis, 1);
  EXPECT_EQ(p.fields->slices[0].index, 5);
  EXPECT_EQ(p.fields->slices[0].name, "slice_y5");
  EXPECT_EQ(p.fields->slices[1].index, 29);  // the far face is clamped to the last node
  ASSERT_TRUE(p.series);
  EXPECT_EQ(p.series->every, 1);  // shorter than dt: every step
  EXPECT_EQ(p.stability.interval, 7);
  EXPECT_EQ(p.stability.last_good, "lg.h5");
}

TEST(OutputScene, ValidationKeys) {
  const FluidOutputParams p =
      parse("  validation: {case: taylor_green, amplitude: 0.01, plane: zx, tolerance: 0.02}\n");
  ASSERT_TRUE(p.validation);
  EXPECT_EQ(p.validation->kind, ValidationCase::taylor_green);
  EXPECT_EQ(p.validation->plane, (std::array<int, 2>{2, 0}));
  EXPECT_DOUBLE_EQ(p.validation->tolerance, 0.02);
}

TEST(OutputScene, MistakesNameFileKeyAndWhatIsExpected) {
  std::string e = error_of("  output: {fields: {interval: 1, velocity: false}}\n");
  EXPECT_NE(e.find("o.yaml:2"), std::string::npos) << e;
  EXPECT_NE(e.find("fluid.output.fields"), std::string::npos) << e;
  EXPECT_NE(e.find("at least one of velocity, density, pressure"), std::string::npos) << e;

  e = error_of("  output: {directory: x}\n");
  EXPECT_NE(e.find("asks for nothing"), std::string::npos) << e;

  e = error_of("  output: {fields: {interval: 1, slices: [{axis: z, position: 0.5}]}}\n");
  EXPECT_NE(e.find("fluid.output.fields.slices[0].position"), std::string::npos) << e;

  e = error_of("  output: {series: {interval: 1, cadence: 2}}\n");
  EXPECT_NE(e.find("unknown key"), std::string::npos) << e;

  e = error_of("  stability: {max_mach: 2}\n");
  EXPECT_NE(e.find("fluid.stability.max_mach"), std::string::npos) << e;

  e = error_of("  validation: {case: taylor_green}\n");
  EXPECT_NE(e.find("amplitude"), std::string::npos) << e;
}

}  // namespace
}  // namespace lbdem
