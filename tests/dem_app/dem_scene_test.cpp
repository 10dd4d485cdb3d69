#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/contact/contact_model.hpp"
#include "dem_app/external_load.hpp"
#include "dem_app/setup/dem_setup.hpp"
#include "dem_scene_text.hpp"

namespace lbdem {
namespace {

const std::string kBase = R"(
name: t
time: {end: 0.1}
dem:
  box: {lo: [0, 0, 0], hi: [0.1, 0.1, 0.1]}
  walls: [{axis: z, side: lo}]
shapes:
  - {name: ball, kind: sphere, diameter: 0.01}
  - {name: cube, kind: cube, edge: 0.01, clump: {method: surface, grid: 3}}
)";

using test::error_of;
using test::parse;
using test::setup_of;

TEST(DemSection, PaperDefaults) {
  const Scene s = parse(kBase + "bodies: []\n");
  ASSERT_TRUE(s.dem);
  EXPECT_EQ(s.dem->material.young_modulus, 5e4);
  EXPECT_EQ(s.dem->material.poisson_ratio, 0.3);
  EXPECT_EQ(s.dem->material.restitution, 0.9);
  EXPECT_EQ(s.dem->material.friction, 0.6);
  EXPECT_EQ(s.dem->dt_fraction, 0.05);
}

TEST(DemSection, RejectsBadPeriodicLetters) {
  std::string text = kBase;
  text.replace(text.find("  walls"), 0, "  periodic: xw\n");
  try {
    parse(text);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("dem.periodic"), std::string::npos) << e.what();
  }
}

TEST(Bodies, LatticeGeneratorPlacesCountWithoutOverlap) {
  const Scene s = parse(kBase + R"(bodies:
  - {generate: lattice, shape: cube, density: 2500, count: 20, seed: 5,
     region: {lo: [0, 0, 0], hi: [0.1, 0.1, 0.1]}}
)");
  ASSERT_EQ(s.bodies.size(), 20u);
  for (const auto& b : s.bodies)
    EXPECT_NEAR(std::hypot(b.orientation[0], b.orientation[1],
                           std::hypot(b.orientation[2], b.orientation[3])),
                1.0, 1e-12);
  EXPECT_EQ(error_of(kBase + R"(bodies:
  - {generate: lattice, shape: cube, density: 2500, count: 20, seed: 5,
     region: {lo: [0, 0, 0], hi: [0.1, 0.1, 0.1]}}
)"),
            "");
}

TEST(Bodies, RandomGeneratorIsDeterministicAndFillsSolidFraction) {
  const std::string text = kBase + R"(bodies:
  - {generate: random, shape: ball, density: 2500, solid_fraction: 0.1, seed: 9,
     region: {lo: [0, 0, 0], hi: [0.1, 0.1, 0.1]}}
)";
  const Scene a = parse(text), b = parse(text);
  // phi V / (pi d^3 / 6) = 0.1 * 1e-3 / 5.236e-7 = 191 spheres.
  ASSERT_EQ(a.bodies.size(), 191u);
  for (size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].position, b.bodies[i].position);
    EXPECT_EQ(a.bodies[i].orientation, b.bodies[i].orientation);
  }
  EXPECT_EQ(error_of(text), "");  // no overlaps, inside the box, clear of the wall
}

TEST(Bodies, GeneratorThatCannotFitNamesTheProblem) {
  try {
    parse(kBase + R"(bodies:
  - {generate: lattice, shape: cube, density: 2500, count: 5000,
     region: {lo: [0, 0, 0], hi: [0.1, 0.1, 0.1]}}
)");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("do not fit"), std::string::npos) << e.what();
  }
}

TEST(DemSetupValidation, RejectsBodyOutsideTheBox) {
  const auto m =
      error_of(kBase + "bodies:\n  - {shape: ball, position: [0.2, 0.05, 0.05], density: 1000}\n");
  EXPECT_NE(m.find("outside the box along x"), std::string::npos) << m;
}

TEST(DemSetupValidation, RejectsBodyThroughAWall) {
  // A cube turned 45 degrees about y reaches 7.07 mm below its centre: through a floor at
  // z = 0.01 when centred at z = 0.016, although its unrotated faces would clear it.
  std::string text = kBase;
  text.replace(text.find("side: lo}"), 9, "side: lo, position: 0.01}");
  const auto m = error_of(text +
                          "bodies:\n  - {shape: cube, position: [0.05, 0.05, 0.016], density: 1000,"
                          " orientation: [0.9238795, 0, 0.3826834, 0]}\n");
  EXPECT_NE(m.find("overlaps dem.walls[0]"), std::string::npos) << m;
}

TEST(DemSetupValidation, RejectsOverlappingBodies) {
  const auto m =
      error_of(kBase +
               "bodies:\n  - {shape: ball, position: [0.05, 0.05, 0.05], density: 1000}\n"
               "  - {shape: ball, position: [0.059, 0.05, 0.05], density: 1000}\n");
  EXPECT_NE(m.find("overlap initially"), std::string::npos) << m;
}

TEST(DemSetupValidation, RejectsMissingBodiesAndWallOnPeriodicAxis) {
  EXPECT_NE(error_of(kBase + "bodies: []\n").find("no bodies"), std::string::npos);
  std::string text = kBase;
  text.replace(text.find("  walls"), 0, "  periodic: z\n");
  const auto m =
      error_of(text + "bodies:\n  - {shape: ball, position: [0.05, 0.05, 0.05], density: 1000}\n");
  EXPECT_NE(m.find("periodic axis"), std::string::npos) << m;
}

TEST(DemSetupValidation, RejectsUnreachableRestitution) {
  std::string text = kBase;
  text.replace(text.find("  walls"), 0, "  material: {restitution: 0.05}\n");
  const auto m =
      error_of(text + "bodies:\n  - {shape: ball, position: [0.05, 0.05, 0.05], density: 1000}\n");
  EXPECT_NE(m.find("dem.material.restitution"), std::string::npos) << m;
}

TEST(DemTimeStep, FractionOfRayleighTimeOfSmallestSphere) {
  const auto s =
      setup_of(kBase + "bodies:\n  - {shape: ball, position: [0.05, 0.05, 0.05], density: 2500}\n");
  // t_R = pi r / (0.8766 + 0.163 nu) sqrt(rho / G), G = E / (2 (1 + nu)) (paper's table).
  const double g = 5e4 / 2.6, beta = 0.8766 + 0.163 * 0.3;
  const double t_r = 3.141592653589793 * 0.005 / beta * std::sqrt(2500 / g);
  EXPECT_NEAR(dem_time_step(s), 0.05 * t_r, 1e-15);
}

TEST(ForceWeights, CancelTheMomentForAnyClump) {
  const Scene sc = parse(kBase + "bodies: []\n");
  for (const auto& shape : build_scene_shapes(sc)) {
    const auto w = force_weights(shape.clump);
    double sum = 0;
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < w.size(); ++i) {
      sum += w[i];
      moment += w[i] * shape.clump.centers[i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12) << shape.name;
    EXPECT_LT(moment.norm(), 1e-15) << shape.name;
  }
  Clump offset;  // one sphere away from the centre of mass: no torque-free spread exists
  offset.centers = {Eigen::Vector3d(0.001, 0, 0)};
  offset.radii = {0.002};
  EXPECT_THROW(force_weights(offset), std::invalid_argument);
}

}  // namespace
}  // namespace lbdem
