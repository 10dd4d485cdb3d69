#include <gtest/gtest.h>

#include "coupler_lib/scene/scene.hpp"

namespace lbdem {
namespace {

Scene parse(const std::string& fluid) {
  return parse_scene(Section::load_string("time: {end: 1.0}\nfluid:\n" + fluid, "u.yaml"), 0);
}

const std::string kBase = "  domain: [0.01, 0.01, 0.01]\n  dx: 0.001\n  viscosity: 1.0e-6\n";

std::string error_of(const std::string& fluid) {
  try {
    parse(fluid);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(Units, DerivedNumbers) {
  const Scene s = parse(kBase + "  tau: 0.8\n  characteristic_velocity: 0.001\n");
  const UnitConverter& u = s.fluid->units;
  EXPECT_DOUBLE_EQ(u.dt, 0.3 * 1e-6 / 3e-6);  // (tau - 1/2) dx^2 / (3 nu)
  EXPECT_NEAR(u.nu_lattice(), 0.1, 1e-15);
  EXPECT_NEAR(u.expected_mach(), 0.001 / (0.001 / 0.1) * std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(u.expected_reynolds(), 0.001 * 0.01 / 1e-6, 1e-9);
  EXPECT_NE(u.describe().find("Mach"), std::string::npos);
}

TEST(Units, ResolutionAsCellsAcrossALength) {
  const Scene s = parse(
      "  domain: [0.01, 0.01, 0.02]\n  resolution: {length: 0.002, cells: 8}\n"
      "  viscosity: 1.0e-6\n");
  EXPECT_DOUBLE_EQ(s.fluid->dx, 0.00025);
  EXPECT_EQ(s.fluid->cells[2], 80);
}

TEST(Units, RefusesTauTooCloseToOneHalf) {
  const std::string m = error_of(kBase + "  tau: 0.502\n");
  EXPECT_NE(m.find("fluid.tau"), std::string::npos) << m;
  EXPECT_NE(m.find("Raise fluid.tau"), std::string::npos) << m;
}

TEST(Units, RefusesHighMachWithAdvice) {
  // dt = 0.1 s: 0.01 m/s is one lattice unit, Ma = sqrt(3).
  const std::string m = error_of(kBase + "  tau: 0.8\n  characteristic_velocity: 0.01\n");
  EXPECT_NE(m.find("fluid.characteristic_velocity"), std::string::npos) << m;
  EXPECT_NE(m.find("Mach"), std::string::npos) << m;
  EXPECT_NE(m.find("refine dx"), std::string::npos) << m;
}

TEST(Units, BoundaryKeys) {
  const Scene s = parse(kBase +
                        "  boundaries:\n    y_min: wall\n    y_max: wall\n"
                        "    z_min: {type: pressure, pressure: 2.5}\n"
                        "    z_max: {type: moving_wall, velocity: [0.001, 0, 0]}\n");
  EXPECT_EQ(s.fluid->faces[0].type, FaceType::periodic);
  EXPECT_EQ(s.fluid->faces[2].type, FaceType::wall);
  EXPECT_EQ(s.fluid->faces[4].type, FaceType::pressure);
  EXPECT_DOUBLE_EQ(s.fluid->faces[4].pressure, 2.5);
  EXPECT_EQ(s.fluid->faces[5].type, FaceType::moving_wall);
  EXPECT_DOUBLE_EQ(s.fluid->faces[5].velocity[0], 0.001);
}

TEST(Units, BoundaryErrorsNameTheFace) {
  std::string m = error_of(kBase + "  boundaries: {x_min: wall}\n");
  EXPECT_NE(m.find("fluid.boundaries.x_min"), std::string::npos) << m;
  EXPECT_NE(m.find("x_max must both be periodic"), std::string::npos) << m;
  m = error_of(kBase + "  boundaries: {z_min: moving_wall, z_max: wall}\n");
  EXPECT_NE(m.find("velocity"), std::string::npos) << m;
  m = error_of(kBase +
               "  boundaries: {z_min: {type: moving_wall, velocity: [0, 0, 1]}, z_max: wall}\n");
  EXPECT_NE(m.find("normal"), std::string::npos) << m;
  m = error_of(kBase + "  boundaries: {z_min: wal, z_max: wall}\n");
  EXPECT_NE(m.find("did you mean 'wall'"), std::string::npos) << m;
}

}  // namespace
}  // namespace lbdem
