// The band's hydrodynamic-radius calibration: the measured table, the scene key that applies it
// and the shapes it changes (only what the fluid sees).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/build_shape.hpp"
#include "coupler_lib/geometry/mass_properties.hpp"
#include "coupler_lib/scene/band_calibration.hpp"
#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"

namespace lbdem {
namespace {

const double kPi = std::acos(-1.0);

TEST(BandCalibration, TableGivesTheMeasuredExcessAndFallsWithTau) {
  // Measured points are returned as measured (tools/calibrate_band.py, d/dx 8).
  EXPECT_DOUBLE_EQ(*band_radius_excess_cells(0.6, PorosityLookup::nearest), 0.353);
  EXPECT_DOUBLE_EQ(*band_radius_excess_cells(1.0, PorosityLookup::nearest), -0.129);
  EXPECT_DOUBLE_EQ(*band_radius_excess_cells(0.6, PorosityLookup::trilinear), 0.372);
  // Between them, monotone: more viscous exchange per step, a thinner effective band.
  double last = *band_radius_excess_cells(0.505, PorosityLookup::nearest);
  for (int i = 51; i <= 300; ++i) {
    const double tau = i / 100.0;
    const double e = *band_radius_excess_cells(tau, PorosityLookup::nearest);
    EXPECT_LT(e, last) << tau;
    last = e;
    // The trilinear band is wider than the nearest one at every tau.
    EXPECT_GT(*band_radius_excess_cells(tau, PorosityLookup::trilinear), e) << tau;
  }
  // Interpolation in ln(tau - 1/2): halfway in that variable, halfway in the excess.
  const double mid = 0.5 + std::sqrt(0.3 * 0.4);  // between tau 0.8 and 0.9
  EXPECT_NEAR(*band_radius_excess_cells(mid, PorosityLookup::nearest), 0.5 * (0.055 - 0.044),
              1e-12);
  EXPECT_FALSE(band_radius_excess_cells(0.5001, PorosityLookup::nearest));
  EXPECT_FALSE(band_radius_excess_cells(3.5, PorosityLookup::nearest));
  // The drag was checked from tau 0.52 to 1.5 (tools/band_size_series.py); outside, inside the
  // measured range, the table applies and fluid_app warns.
  EXPECT_TRUE(band_calibration_checked(0.52) && band_calibration_checked(1.5));
  EXPECT_FALSE(band_calibration_checked(0.51) || band_calibration_checked(2.0));
}

const char* kCoupled = R"(
name: c
time: {end: 1.0e-3}
fluid:
  domain: [2.0e-3, 2.0e-3, 2.0e-3]
  dx: 1.0e-4
  viscosity: 1.0e-6
  tau: 0.6
dem: {periodic: xyz}
shapes:
  - {name: ball, kind: sphere, diameter: 8.0e-4}
  - {name: box, kind: cuboid, edges: [8.0e-4, 6.0e-4, 4.0e-4]}
bodies:
  - {shape: ball, position: [1.0e-3, 1.0e-3, 1.0e-3], density: 2500}
)";

Scene parse(const std::string& text) {
  return parse_scene(Section::load_string(text, "c.yaml"), 0);
}

std::string with(const std::string& key) {
  std::string text = kCoupled;
  text.insert(text.find("  tau: 0.6\n") + 11, key);
  return text;
}

TEST(BandCalibration, CalibratedIsTheDefaultAndShrinksOnlyWhatTheFluidSees) {
  const Scene cal = parse(kCoupled), nom = parse(with("  hydrodynamic_radius: nominal\n"));
  EXPECT_EQ(cal.fluid->hydrodynamic_radius, HydrodynamicRadius::calibrated);
  EXPECT_EQ(nom.fluid->hydrodynamic_radius, HydrodynamicRadius::nominal);
  const auto a = build_scene_shapes(cal), b = build_scene_shapes(nom);
  const double delta = 0.353 * 1.0e-4;  // tau 0.6, nearest
  // Sphere: the fluid's lattice holds a sphere of radius a - delta (volume fractions: exact to
  // about 1e-3 at 16 voxels across); mass, inertia and the contact sphere stay the true ones.
  const double r = 4.0e-4;
  EXPECT_NEAR(a[0].reference_volume / (4.0 / 3.0 * kPi * std::pow(r - delta, 3)), 1.0, 2e-3);
  EXPECT_NEAR(b[0].reference_volume / (4.0 / 3.0 * kPi * std::pow(r, 3)), 1.0, 2e-3);
  EXPECT_EQ(a[0].mass.volume, b[0].mass.volume);
  EXPECT_EQ((a[0].mass.inertia - b[0].mass.inertia).norm(), 0.0);
  EXPECT_DOUBLE_EQ(a[0].clump.radii[0], r);
  EXPECT_LT(mass_properties(a[0].voxels).centroid.norm(), 1e-12);
  // Cuboid: every face moved inward by delta (an eroded box is a box); exact up to the float
  // volume fractions.
  EXPECT_NEAR(
      a[1].reference_volume / ((8.0e-4 - 2 * delta) * (6.0e-4 - 2 * delta) * (4.0e-4 - 2 * delta)),
      1.0, 1e-7);
  EXPECT_EQ(a[1].mass.volume, b[1].mass.volume);
}

ShapeParams params(const std::string& kind, double size, std::array<double, 3> extents) {
  ShapeParams p;
  p.name = kind;
  p.kind = value_of(kShapeKindWords, kind);
  p.size = size;
  p.extents = extents;
  return p;
}

TEST(BandCalibration, OffsetOfEachKind) {
  const ShapeParams sphere = params("sphere", 2.0, {1, 1, 1});
  const ShapeParams s = offset_params(sphere, 0.1);
  EXPECT_DOUBLE_EQ(s.size, 1.8);
  EXPECT_DOUBLE_EQ(s.extents[0], 0.9);
  EXPECT_DOUBLE_EQ(offset_params(params("cube", 1.0, {1, 1, 1}), 0.1).extents[1], 0.8);
  // Ellipsoids and meshes are eroded on the fluid's lattice instead (offset_voxels.hpp): the
  // shipped cube STL with its surface moved inward by edge / 80 embeds the cube of edge
  // 0.975 edge (faces on sub-column boundaries at spacing edge / 20, so exactly).
  EXPECT_FALSE(offset_is_a_parameter(ShapeKind::ellipsoid));
  EXPECT_FALSE(offset_is_a_parameter(ShapeKind::stl));
  ShapeParams stl = params("stl", 1.0, {1, 1, 1});
  stl.file = std::string(LBDEM_SOURCE_DIR) + "/configs/shapes/cube.stl";
  const double edge = make_solid(stl).upper().x() - make_solid(stl).lower().x();
  stl.hydrodynamic_offset = edge / 80;
  const Shape m = build_shape(stl, edge / 20);
  EXPECT_NEAR(m.reference_volume / std::pow(0.975 * edge, 3), 1.0, 1e-6);
  EXPECT_NEAR(m.mass.volume / std::pow(edge, 3), 1.0, 1e-12);
  // Too thin for the offset: a clear error naming the key.
  try {
    offset_params(sphere, 1.0);
    FAIL() << "expected a ShapeError";
  } catch (const ShapeError& err) {
    EXPECT_NE(std::string(err.what()).find("fluid.hydrodynamic_radius"), std::string::npos);
  }
}

TEST(BandCalibration, OutsideTheMeasuredTausCalibratedIsRefusedNominalWorks) {
  std::string text = kCoupled;
  text.replace(text.find("tau: 0.6"), 8, "tau: 4.0");
  try {
    parse(text);
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("c.yaml"), std::string::npos) << m;
    EXPECT_NE(m.find("fluid.hydrodynamic_radius"), std::string::npos) << m;
    EXPECT_NE(m.find("nominal"), std::string::npos) << m;
  }
  text.insert(text.find("  tau: 4.0\n") + 11, "  hydrodynamic_radius: nominal\n");
  EXPECT_EQ(parse(text).fluid->hydrodynamic_radius, HydrodynamicRadius::nominal);
  try {
    parse(with("  hydrodynamic_radius: smaller\n"));
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("calibrated"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lbdem
