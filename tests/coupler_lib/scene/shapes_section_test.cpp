// The `shapes:` scene keys, the voxel spacing the shape catalogue picks, and build_shape:
// parameters -> voxels in the shape frame, mass properties, clump and its quality.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/build_shape.hpp"
#include "coupler_lib/geometry/mass_properties.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "coupler_lib/scene/shapes_section.hpp"

namespace lbdem {
namespace {

// A scene "located" in configs/, so relative paths resolve to the shipped shapes.
const std::string kSceneName = std::string(LBDEM_SOURCE_DIR) + "/configs/test_scene.yaml";

std::vector<ShapeParams> parse(const std::string& yaml) {
  Section root = Section::load_string(yaml, kSceneName);
  auto shapes = parse_shapes(root);
  root.finish();
  return shapes;
}

std::string parse_error(const std::string& yaml) {
  try {
    parse(yaml);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(ShapesSection, ParsesEveryKind) {
  const auto s = parse(R"(
shapes:
  - {name: ball, kind: sphere, diameter: 2.0e-3}
  - {name: dice, kind: cube, edge: 1.0e-3, clump: {file: shapes/cube_489_surface.clump, scale: 1.0e-3}}
  - {name: brick, kind: cuboid, edges: [3, 2, 1], clump: {method: fill, spheres: 20}}
  - {name: egg, kind: ellipsoid, semi_axes: [1, 0.5, 0.5], voxel_size: 0.05}
  - {name: mesh, kind: stl, file: shapes/cube.stl, scale: 2.0,
     clump: {method: surface, grid: 10, radius_ratio: 0.8, center_sphere: false}}
)");
  ASSERT_EQ(s.size(), 5u);
  EXPECT_EQ(s[0].kind, ShapeKind::sphere);
  EXPECT_DOUBLE_EQ(s[0].size, 2.0e-3);
  EXPECT_EQ(s[0].clump.source, ClumpSource::shape_default);
  EXPECT_EQ(s[1].clump.source, ClumpSource::file);
  EXPECT_NE(s[1].clump.file.find("configs/shapes/cube_489_surface.clump"), std::string::npos);
  EXPECT_DOUBLE_EQ(s[1].clump.scale, 1.0e-3);
  EXPECT_DOUBLE_EQ(s[2].size, 3.0);
  EXPECT_EQ(s[2].clump.source, ClumpSource::fill);
  EXPECT_EQ(s[2].clump.spheres, 20);
  EXPECT_DOUBLE_EQ(s[3].size, 2.0);
  EXPECT_DOUBLE_EQ(s[3].voxel_size, 0.05);
  EXPECT_EQ(s[4].kind, ShapeKind::stl);
  EXPECT_DOUBLE_EQ(s[4].size, 2.0);  // unit cube STL scaled by 2
  EXPECT_EQ(s[4].clump.grid, 10);
  EXPECT_FALSE(s[4].clump.center_sphere);
}

TEST(ShapesSection, ErrorsNameTheKeyAndWhatWasExpected) {
  EXPECT_NE(
      parse_error("shapes: [{name: a, kind: sphere}]").find("missing required key 'diameter'"),
      std::string::npos);
  EXPECT_NE(parse_error("shapes: [{name: a, kind: cylinder, diameter: 1}]").find("expected one of"),
            std::string::npos);
  const std::string missing = parse_error("shapes: [{name: a, kind: stl, file: nope.stl}]");
  EXPECT_NE(missing.find("shapes[0].file"), std::string::npos) << missing;
  EXPECT_NE(missing.find("not found"), std::string::npos) << missing;
  EXPECT_NE(parse_error("shapes: [{name: a, kind: cube, edge: 1, clump: {method: fill}}]")
                .find("'spheres'"),
            std::string::npos);
  EXPECT_NE(parse_error("shapes: [{name: a, kind: cube, edge: 1, clump: {method: fill, "
                        "spheres: 3, methd: x}}]")
                .find("did you mean 'method'"),
            std::string::npos);
  EXPECT_NE(parse_error("shapes: [{name: a, kind: cube, edge: 1, clump: {file: "
                        "shapes/cube_27_fill.clump, method: fill}}]")
                .find("not both"),
            std::string::npos);
  EXPECT_NE(parse_error("shapes: [{name: a, kind: cube, edge: -1}]").find("> 0"),
            std::string::npos);
  EXPECT_NE(parse_error("shapes: [{name: a, kind: cube, edge: 1}, {name: a, kind: cube, edge: 2}]")
                .find("already in the catalogue"),
            std::string::npos);
  EXPECT_NE(parse_error("shapes: [{name: a, kind: cuboid, edges: [1, 2]}]").find("3 numbers"),
            std::string::npos);
}

TEST(ShapesSection, BrokenStlIsReportedAtTheFileKey) {
  // The binary sphere renamed as ASCII would still parse; a clump file is not an STL.
  const std::string e =
      parse_error("shapes: [{name: a, kind: stl, file: shapes/cube_27_fill.clump}]");
  EXPECT_NE(e.find("shapes[0].file"), std::string::npos) << e;
  EXPECT_NE(e.find("not an STL file"), std::string::npos) << e;
}

TEST(BuildShape, VoxelSpacingDefaults) {
  ShapeParams p;
  p.size = 1.0;
  std::optional<FluidParams> fluid;
  EXPECT_DOUBLE_EQ(shape_voxel_spacing(p, fluid), 1.0 / 40);
  fluid = FluidParams{};
  fluid->dx = 0.1;
  EXPECT_DOUBLE_EQ(shape_voxel_spacing(p, fluid), 0.05);
  p.voxel_size = 0.02;
  EXPECT_DOUBLE_EQ(shape_voxel_spacing(p, fluid), 0.02);
}

TEST(BuildShape, StlCubeEqualsAnalyticCubeInTheShapeFrame) {
  const auto s = parse(R"(
shapes:
  - {name: stl, kind: stl, file: shapes/cube.stl, scale: 2.0e-3,
     clump: {file: shapes/cube_489_surface.clump, scale: 2.0e-3}}
  - {name: analytic, kind: cube, edge: 2.0e-3, clump: {file: shapes/cube_489_surface.clump, scale: 2.0e-3}}
)");
  const double h = 2.0e-3 / 24;
  const Shape a = build_shape(s[0], h), b = build_shape(s[1], h);
  EXPECT_EQ(a.voxels.solid, b.voxels.solid);
  EXPECT_NEAR(a.mass.volume, 8e-9, 1e-20);
  EXPECT_NEAR((a.mass.inertia - b.mass.inertia).norm(), 0.0, 1e-25);
  EXPECT_NEAR(a.mass.inertia(0, 0), 8e-9 * 4e-6 / 6, 1e-26);  // V a^2 / 6
  // Shape frame: the voxels' own centroid is the origin.
  EXPECT_LT(mass_properties(a.voxels).centroid.norm(), 1e-15);
  // The reference lattice (voxels of h / 2 holding the fill of a box h) reaches one voxel of
  // h / 2 beyond the faces.
  EXPECT_DOUBLE_EQ(a.voxels.h, h / 2);
  EXPECT_DOUBLE_EQ(a.voxel_spacing, h);
  EXPECT_NEAR(a.bounding_radius, std::sqrt(3.0) * (1e-3 + h / 2), 1e-15);
  EXPECT_EQ(a.clump.size(), 489u);
  std::printf("cube_489 at 24 voxels across: volume error %.4f, deviation %.3g m\n",
              a.clump_quality.volume_error, a.clump_quality.max_deviation);
  EXPECT_LT(a.clump_quality.volume_error, 0.08);
}

TEST(BuildShape, OffCentreStlIsMovedToTheShapeFrame) {
  const auto s = parse("shapes: [{name: m, kind: stl, file: shapes/sphere.stl}]");
  const Shape sh = build_shape(s[0], 1.0 / 30);
  // The icosphere is centred at the STL origin: the centroid stays there (symmetric lattice).
  EXPECT_LT(sh.mass.centroid.norm(), 1e-12);
  EXPECT_LT(mass_properties(sh.voxels).centroid.norm(), 1e-12);
  EXPECT_EQ(sh.clump_source, "fill spheres=100");  // the default for non-spheres
  EXPECT_LE(sh.clump.size(), 100u);
  // One layer of empty voxels at least.
  const Voxels& v = sh.voxels;
  for (int j = 0; j < v.n[1]; ++j)
    for (int i = 0; i < v.n[0]; ++i) {
      ASSERT_EQ(v.solid[v.index(i, j, 0)], 0);
      ASSERT_EQ(v.solid[v.index(i, j, v.n[2] - 1)], 0);
    }
}

TEST(BuildShape, SphereDefaultsToItsExactClump) {
  const auto s = parse("shapes: [{name: b, kind: sphere, diameter: 0.01}]");
  const Shape sh = build_shape(s[0], 0.01 / 20);
  ASSERT_EQ(sh.clump.size(), 1u);
  EXPECT_DOUBLE_EQ(sh.clump.radii[0], 0.005);
  EXPECT_LT(sh.clump.centers[0].norm(), 1e-15);
  EXPECT_NEAR(sh.mass.volume, M_PI / 6 * 1e-6, 0.03 * M_PI / 6 * 1e-6);
}

TEST(BuildShape, ClumpFileAtTheWrongScaleIsRejected) {
  const auto s = parse(
      "shapes: [{name: c, kind: cube, edge: 1.0e-3, clump: {file: shapes/cube_27_fill.clump}}]");
  try {
    build_shape(s[0], 1.0e-3 / 20);
    FAIL() << "expected a ShapeError";
  } catch (const ShapeError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("does not fit the shape"), std::string::npos) << m;
    EXPECT_NE(m.find("clump.scale"), std::string::npos) << m;
    EXPECT_NE(m.find("test_scene.yaml"), std::string::npos) << m;
  }
}

// The paper's enlarged hydrodynamic radius: the fluid's voxels are those of the scaled sphere,
// the mass, inertia and contact sphere stay those of the true one.
TEST(BuildShape, HydrodynamicScaleEnlargesOnlyWhatTheFluidSees) {
  const auto s = parse(R"(
shapes:
  - {name: true, kind: sphere, diameter: 1.0e-3}
  - {name: wet, kind: sphere, diameter: 1.0e-3, hydrodynamic_scale: 1.05}
)");
  EXPECT_DOUBLE_EQ(s[0].hydrodynamic_scale, 1.0);
  EXPECT_DOUBLE_EQ(s[1].hydrodynamic_scale, 1.05);
  const double h = 1.0e-3 / 32;
  const Shape a = build_shape(s[0], h), b = build_shape(s[1], h);
  EXPECT_EQ(a.mass.volume, b.mass.volume);
  EXPECT_EQ((a.mass.inertia - b.mass.inertia).norm(), 0.0);
  ASSERT_EQ(b.clump.size(), 1u);
  EXPECT_DOUBLE_EQ(b.clump.radii[0], 0.5e-3);
  // The fluid's lattice is the voxelization of a 1.05 mm sphere at the same spacing, centred
  // on the body.
  ShapeParams big = s[0];
  big.size = 1.05e-3;
  const Shape c = build_shape(big, h);
  EXPECT_EQ(b.voxels.solid, c.voxels.solid);
  EXPECT_EQ(b.voxels.n, c.voxels.n);
  const double exact = std::acos(-1.0) / 6 * std::pow(1.05e-3, 3);
  EXPECT_NEAR(mass_properties(b.voxels).volume / exact, 1.0, 0.02);
  EXPECT_LT(mass_properties(b.voxels).centroid.norm(), 1e-12);
  EXPECT_NEAR(b.bounding_radius / a.bounding_radius, 1.05, 0.01);
  EXPECT_NE(parse_error("shapes: [{name: a, kind: sphere, diameter: 1, hydrodynamic_scale: 3}]")
                .find("hydrodynamic_scale"),
            std::string::npos);
}

TEST(BuildShape, TooCoarseSpacingIsAnError) {
  const auto s = parse("shapes: [{name: b, kind: sphere, diameter: 0.01}]");
  EXPECT_THROW(build_shape(s[0], 0.2), ShapeError);
}

}  // namespace
}  // namespace lbdem
