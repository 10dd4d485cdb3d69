// The lubrication law (dem_app/lubrication_law.hpp) and the dem.lubrication scene keys.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/dem_setup.hpp"
#include "dem_app/lubrication_law.hpp"

namespace lbdem {
namespace {

constexpr double kPi = std::numbers::pi;
const LubricationLaw kLaw{1e-3, 1e-4, 1e-6};  // mu, h_c, h_min

TEST(LubricationLaw, CoefficientsOfEqualSpheresAndOfAWall) {
  const auto eq = squeeze_coefficients(2e-3, 2e-3);
  EXPECT_DOUBLE_EQ(eq.g1, 0.25);
  EXPECT_DOUBLE_EQ(eq.g2, 9.0 / 40.0);
  const auto wall = squeeze_coefficients(2e-3, 0.0);
  EXPECT_DOUBLE_EQ(wall.g1, 1.0);
  EXPECT_DOUBLE_EQ(wall.g2, 0.2);
  // A very large second sphere tends to the wall.
  const auto big = squeeze_coefficients(2e-3, 2e3);
  EXPECT_NEAR(big.g1, 1.0, 1e-5);
  EXPECT_NEAR(big.g2, 0.2, 1e-5);
}

TEST(LubricationLaw, ZeroBeyondTheCutoffContinuousAtItSaturatedBelowTheMinimum) {
  const double a = 1e-3;
  EXPECT_EQ(lubrication_resistance(kLaw, a, a, kLaw.cutoff), 0.0);
  EXPECT_EQ(lubrication_resistance(kLaw, a, a, 2 * kLaw.cutoff), 0.0);
  const double just_below = lubrication_resistance(kLaw, a, a, kLaw.cutoff * (1 - 1e-9));
  EXPECT_GT(just_below, 0.0);
  EXPECT_LT(just_below, 1e-8 * lubrication_resistance(kLaw, a, a, 0.5 * kLaw.cutoff));
  const double at_min = lubrication_resistance(kLaw, a, 0.0, kLaw.min_gap);
  EXPECT_EQ(lubrication_resistance(kLaw, a, 0.0, 0.1 * kLaw.min_gap), at_min);
  EXPECT_EQ(lubrication_resistance(kLaw, a, 0.0, -1e-5), at_min);  // overlapping contact
  // Monotone in the gap.
  double last = at_min;
  for (double h = 2 * kLaw.min_gap; h < kLaw.cutoff; h *= 1.5) {
    const double c = lubrication_resistance(kLaw, a, 0.0, h);
    EXPECT_LT(c, last);
    last = c;
  }
}

TEST(LubricationLaw, SymmetricInTheTwoSpheresNewtonsThirdLaw) {
  for (double h : {2e-6, 1e-5, 5e-5}) {
    const double c12 = lubrication_resistance(kLaw, 1e-3, 3e-3, h);
    const double c21 = lubrication_resistance(kLaw, 3e-3, 1e-3, h);
    EXPECT_NEAR(c12, c21, 1e-13 * c12);
  }
}

TEST(LubricationLaw, LeadingTermIsReynoldsSqueezeFilm) {
  // Far below h_c the correction is dominated by 6 pi mu a_eff^2 / h, a_eff = a1 a2 / (a1 + a2)
  // (Reynolds lubrication; Brenner 1961 for the plane: 6 pi mu a^2 / h).
  const LubricationLaw law{1e-3, 1e-3, 1e-12};
  const double a1 = 1e-3, a2 = 2e-3, h = 1e-9;
  const double aeff = a1 * a2 / (a1 + a2);
  const double lead = 6 * kPi * law.viscosity * aeff * aeff / h;
  EXPECT_NEAR(lubrication_resistance(law, a1, a2, h) / lead, 1.0, 1e-4);
  EXPECT_NEAR(lubrication_resistance(law, a1, 0.0, h) / (6 * kPi * 1e-3 * a1 * a1 / h), 1.0, 1e-4);
}

const std::string kScene = R"(
name: t
time: {end: 0.1}
dem:
  gravity: [0, 0, 0]
  box: {lo: [0, 0, 0], hi: [0.1, 0.1, 0.1]}
  walls: [{axis: z, side: lo}]
  lubrication: LUBE
shapes:
  - {name: ball, kind: sphere, diameter: 0.01}
bodies:
  - {shape: ball, position: [0.05, 0.05, 0.05], density: 2500}
)";

std::string error_of(const std::string& lube) {
  std::string text = kScene;
  text.replace(text.find("LUBE"), 4, lube);
  try {
    const Scene s = parse_scene(Section::load_string(text, "t.yaml"), 0);
    validate_dem_setup(make_dem_setup(s, build_scene_shapes(s), false));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// Goldman, Cox & Brenner (1967) / O'Neill & Stewartson (1967): the log coefficients 8/15, 2/15
// (6 pi mu a^2) and 2/5 (8 pi mu a^3), zero at and beyond h_c, held below h_min, and a
// positive-definite translation-rotation resistance (the correction only dissipates).
TEST(LubricationLaw, WallSlidingFollowsTheLogTermsAndDissipates) {
  const LubricationLaw law{2e-3, 1e-4, 1e-6};
  const double a = 1e-3, pi = std::numbers::pi, h = 1e-5;
  const SlidingResistance s = wall_sliding_resistance(law, a, h);
  const double l = std::log(law.cutoff / h);
  EXPECT_NEAR(s.translation, 6 * pi * law.viscosity * a * 8.0 / 15.0 * l, 1e-15);
  EXPECT_NEAR(s.coupling, 8 * pi * law.viscosity * a * a * 0.1 * l, 1e-18);
  EXPECT_NEAR(s.rotation, 8 * pi * law.viscosity * a * a * a * 0.4 * l, 1e-21);
  EXPECT_EQ(wall_sliding_resistance(law, a, law.cutoff).translation, 0.0);
  EXPECT_EQ(wall_sliding_resistance(law, a, 2 * law.cutoff).rotation, 0.0);
  EXPECT_EQ(wall_sliding_resistance(law, a, 1e-9).translation,
            wall_sliding_resistance(law, a, law.min_gap).translation);
  EXPECT_EQ(wall_sliding_resistance(law, a, -1e-6).coupling,
            wall_sliding_resistance(law, a, law.min_gap).coupling);
  EXPECT_GT(s.translation * s.rotation, s.coupling * s.coupling);
  EXPECT_GT(wall_sliding_resistance(law, a, 2e-6).translation, s.translation);
}

TEST(LubricationKeys, OffByDefaultAndAcceptedWhenComplete) {
  EXPECT_EQ(error_of("{}"), "");
  EXPECT_EQ(error_of("{enabled: true, cutoff: 1e-4, min_gap: 1e-6, viscosity: 1e-3}"), "");
  std::string text = kScene;
  text.replace(text.find("LUBE"), 4,
               "{enabled: true, cutoff: 1e-4, min_gap: 1e-6, viscosity: 1e-3}");
  const Scene s = parse_scene(Section::load_string(text, "t.yaml"), 0);
  EXPECT_TRUE(make_dem_setup(s, build_scene_shapes(s), false).external_loads);
}

TEST(LubricationKeys, RefusedWhenMalformed) {
  EXPECT_NE(error_of("{enabled: true, cutoff: 1e-4, viscosity: 1e-3}").find("min_gap"),
            std::string::npos);
  EXPECT_NE(error_of("{enabled: true, cutoff: 1e-4, min_gap: 1e-6}").find("viscosity"),
            std::string::npos);
  EXPECT_NE(error_of("{enabled: true, min_gap: 1e-6, viscosity: 1e-3}").find("cutoff"),
            std::string::npos);
  EXPECT_NE(error_of("{enabled: true, cutoff: 1e-6, min_gap: 1e-6, viscosity: 1e-3}")
                .find("min_gap: must be below"),
            std::string::npos);
  EXPECT_NE(error_of("{enabled: yes please}").find("enabled"), std::string::npos);
  EXPECT_NE(error_of("{enabled: true, cutof: 1e-4}").find("cutof"), std::string::npos);
  EXPECT_NE(error_of("{enabled: true, cutoff: 1e-4, min_gap: 1e-6, viscosity: 1e-3, tangential: 1}")
                .find("tangential"),
            std::string::npos);
  EXPECT_NE(error_of("{enabled: true, cutoff: -1, min_gap: 1e-6}").find("cutoff"),
            std::string::npos);
  // Too stiff for the DEM step: a tiny minimum gap with a large viscosity.
  EXPECT_NE(
      error_of("{enabled: true, cutoff: 1e-3, min_gap: 1e-12, viscosity: 10}").find("too stiff"),
      std::string::npos);
}

}  // namespace
}  // namespace lbdem
