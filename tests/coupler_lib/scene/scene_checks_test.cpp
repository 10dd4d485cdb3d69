#include "coupler_lib/scene/scene_checks.hpp"

#include <gtest/gtest.h>

namespace lbdem {
namespace {

const std::string kCoupled = R"(
time: {end: 1.0e-3}
fluid: {domain: [1.0e-3, 1.0e-3, 1.0e-3], dx: 1.0e-4, viscosity: 1.0e-6, tau: 0.6}
dem: {periodic: xyz}
shapes: [{name: ball, kind: sphere, diameter: 3.0e-4}]
)";

Scene scene_with(const std::string& bodies, const std::string& text = kCoupled) {
  return parse_scene(Section::load_string(text + bodies, "c.yaml"), 0);
}

std::string refusal(const Scene& s, double memory = 1e12) {
  try {
    check_whole_scene(s, memory);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

const std::string kOne =
    "bodies: [{shape: ball, position: [5.0e-4, 5.0e-4, 5.0e-4], density: 2500}]\n";

TEST(SceneChecks, AValidScenePasses) {
  EXPECT_EQ(refusal(scene_with(kOne)), "");
}

TEST(SceneChecks, MemoryOfTheLatticeIsEstimatedAndRefusedWithTheFigure) {
  const Scene s = scene_with(kOne);
  // 10^3 cells x (2 x 19 x 8 + 8) B.
  EXPECT_DOUBLE_EQ(fluid_memory_bytes(*s.fluid, true), 1000.0 * 312);
  const std::string m = refusal(s, 1000.0 * 312 - 1);
  EXPECT_NE(m.find("10 x 10 x 10 cells needs at least"), std::string::npos) << m;
  EXPECT_NE(m.find("312 B per cell"), std::string::npos) << m;
  EXPECT_EQ(refusal(s, 1000.0 * 312), "");
}

TEST(SceneChecks, OverlappingBodiesAreRefused) {
  const std::string m = refusal(
      scene_with("bodies: [{shape: ball, position: [5.0e-4, 5.0e-4, 5.0e-4], density: 2500},\n"
                 "         {shape: ball, position: [6.0e-4, 5.0e-4, 5.0e-4], density: 2500}]\n"));
  EXPECT_NE(m.find("c.yaml: bodies: body 0 and body 1 overlap initially"), std::string::npos) << m;
}

TEST(SceneChecks, ABodyLargerThanTheBoxIsRefused) {
  std::string text = kCoupled;
  text.replace(text.find("diameter: 3.0e-4"), 16, "diameter: 1.5e-3");
  const std::string m = refusal(scene_with(kOne, text));
  EXPECT_NE(m.find("larger than the box"), std::string::npos) << m;
}

TEST(SceneChecks, ABodyThinnerThanAFluidCellIsRefused) {
  // A flat disc 60 um thick in a lattice of 100 um cells.
  std::string text = kCoupled;
  const std::string sphere = "kind: sphere, diameter: 3.0e-4";
  text.replace(text.find(sphere), sphere.size(),
               "kind: ellipsoid, semi_axes: [3.0e-4, 3.0e-4, 3.0e-5]");
  const std::string m = refusal(scene_with(kOne, text));
  EXPECT_NE(m.find("is 6e-05 m thick, thinner than one fluid cell"), std::string::npos) << m;
}

}  // namespace
}  // namespace lbdem
