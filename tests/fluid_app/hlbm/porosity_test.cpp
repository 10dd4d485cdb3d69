// Porosity field of the homogenized LBM bodies (paper, appendix "Representation of a
// particle in the fluid"): volume, rotation, periodic images, sub-boxes.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "coupler_lib/geometry/voxelize.hpp"
#include "tests/fluid_app/hlbm/hlbm_fixtures.hpp"

namespace lbdem::hlbm {
namespace {

using test::state;

// Sum of (1 - d) over the rank's interior cells, i.e. the embedded solid volume in cells.
double solid_volume(const Subdomain& sub, const PorousField<double>& f) {
  double v = 0;
  const LocalBox& b = sub.box;
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) v += 1.0 - f.d[static_cast<std::size_t>(b.index(x, y, z))];
  return v;
}

TEST(Porosity, SphereVolumeConvergesWithResolution) {
  double previous = 1;
  for (double radius : {3.0, 6.0, 12.0}) {
    const int n = static_cast<int>(2 * radius) + 8;
    const Shape s = test::sphere(radius, 0.5);
    const Subdomain sub = test::whole(n);
    PorousField<double> field;
    BodyField<double> bodies({&s, 1}, sub, test::unit_frame(), field);
    const BodyState st = state(0, Eigen::Vector3d(n / 2.0 + 0.31, n / 2.0 - 0.17, n / 2.0 + 0.05));
    bodies.update({&st, 1});
    const double exact = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
    const double err = std::abs(solid_volume(sub, field) - exact) / exact;
    std::printf("sphere R = %4.1f cells: embedded volume error %.4f %%\n", radius, 100 * err);
    EXPECT_LT(err, previous);
    previous = err;
  }
  EXPECT_LT(previous, 0.01);
}

TEST(Porosity, SurfaceSitsNearHalfPorosity) {
  // Along a ray from the centre of a sphere, d crosses 1/2 within a quarter cell of R.
  const double radius = 8;
  const Shape s = test::sphere(radius, 0.5);
  const Subdomain sub = test::whole(28);
  PorousField<double> field;
  BodyField<double> bodies({&s, 1}, sub, test::unit_frame(), field);
  const BodyState st = state(0, Eigen::Vector3d(14.5, 14.5, 14.5));  // centre on node 14
  bodies.update({&st, 1});
  const LocalBox& b = sub.box;
  // Node g at g + 1/2, local x = g + 1: nodes 14 + k along +x at distance k.
  double crossing = -1;
  for (int k = 0; k < 12; ++k) {
    const float d0 = field.d[static_cast<std::size_t>(b.index(15 + k, 15, 15))];
    const float d1 = field.d[static_cast<std::size_t>(b.index(16 + k, 15, 15))];
    if (d0 < 0.5f && d1 >= 0.5f) crossing = k + (0.5 - d0) / (d1 - d0);
  }
  std::printf("d = 1/2 crossing at r = %.3f cells (R = %.1f)\n", crossing, radius);
  EXPECT_NEAR(crossing, radius, 0.25);
}

TEST(Porosity, QuarterTurnsRotateTheField) {
  // Quarter turns about the centre map lattice nodes onto nodes, so the rotated body's
  // porosity must equal the unrotated one's at the rotated-back node, cell by cell.
  const Shape s = test::cube(8, 0.5);
  const int n = 24;
  const Subdomain sub = test::whole(n);
  const Eigen::Vector3d centre(12, 12, 12);  // between nodes: quarter turns permute nodes
  PorousField<double> f0, f1;
  BodyField<double> plain({&s, 1}, sub, test::unit_frame(), f0);
  BodyField<double> turned({&s, 1}, sub, test::unit_frame(), f1);
  // A non-symmetric shape would be better, but a cube displaced off-centre is not invariant
  // under the turn about the domain centre: place it off the rotation axis.
  const Eigen::Vector3d off(2, -1, 1);
  const Eigen::Quaterniond q = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX());
  const Eigen::Matrix3d r = q.toRotationMatrix();
  const BodyState s0 = state(0, centre + off);
  const BodyState s1 = state(0, centre + r * off, q);
  plain.update({&s0, 1});
  turned.update({&s1, 1});
  const LocalBox& b = sub.box;
  int solid_cells = 0;
  for (int z = 1; z <= n; ++z)
    for (int y = 1; y <= n; ++y)
      for (int x = 1; x <= n; ++x) {
        const Eigen::Vector3d p(x - 0.5, y - 0.5, z - 0.5);
        const Eigen::Vector3d back = centre + r.transpose() * (p - centre);
        const auto c = static_cast<std::size_t>(b.index(x, y, z));
        const auto c0 =
            static_cast<std::size_t>(b.index(static_cast<int>(std::lround(back.x() + 0.5)),
                                             static_cast<int>(std::lround(back.y() + 0.5)),
                                             static_cast<int>(std::lround(back.z() + 0.5))));
        ASSERT_NEAR(f1.d[c], f0.d[c0], 1e-5) << "cell " << x << " " << y << " " << z;
        solid_cells += f1.d[c] < 1.0f;
      }
  EXPECT_GT(solid_cells, 8 * 8 * 8);
}

// Volume and second moments of (1 - d) about the body centre.
struct Moments {
  double volume = 0;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
};
Moments moments(const Subdomain& sub, const PorousField<double>& f, const Eigen::Vector3d& x0) {
  Moments m;
  const LocalBox& b = sub.box;
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const double s = 1.0 - f.d[static_cast<std::size_t>(b.index(x, y, z))];
        const Eigen::Vector3d r = Eigen::Vector3d(x - 0.5, y - 0.5, z - 0.5) - x0;
        m.volume += s;
        m.second += s * r * r.transpose();
      }
  return m;
}

TEST(Porosity, GenericRotationRotatesVolumeAndMoments) {
  const Shape s = test::cube(10, 0.5);
  const Subdomain sub = test::whole(28);
  const Eigen::Vector3d centre(14.2, 13.9, 14.1);
  PorousField<double> f0, f1;
  BodyField<double> plain({&s, 1}, sub, test::unit_frame(), f0);
  BodyField<double> turned({&s, 1}, sub, test::unit_frame(), f1);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const BodyState s0 = state(0, centre), s1 = state(0, centre, q);
  plain.update({&s0, 1});
  turned.update({&s1, 1});
  const Moments m0 = moments(sub, f0, centre), m1 = moments(sub, f1, centre);
  const Eigen::Matrix3d r = q.toRotationMatrix();
  const Eigen::Matrix3d expected = r * m0.second * r.transpose();
  const double vol_err = std::abs(m1.volume - m0.volume) / m0.volume;
  const double mom_err = (m1.second - expected).norm() / expected.norm();
  std::printf("rotated cube: volume error %.4f %%, second-moment error %.4f %%\n", 100 * vol_err,
              100 * mom_err);
  EXPECT_LT(vol_err, 0.005);
  EXPECT_LT(mom_err, 0.01);
}

TEST(Porosity, BodyAcrossPeriodicCornerIsOneBody) {
  const Shape s = test::cube(7, 0.5);
  const int n = 30;
  const Subdomain sub = test::whole(n);
  PorousField<double> fa, fb;
  BodyField<double> middle({&s, 1}, sub, test::unit_frame(), fa);
  BodyField<double> corner({&s, 1}, sub, test::unit_frame(), fb);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -1, 2).normalized()));
  const Eigen::Vector3d xa(15.3, 14.6, 15.1);
  const std::array<int, 3> shift = {14, 15, 15};  // puts the centre at (29.3, 29.6, 30.1 -> 0.1)
  const BodyState sa = state(0, xa, q);
  const BodyState sb = state(0, xa + Eigen::Vector3d(shift[0], shift[1], shift[2]), q);
  middle.update({&sa, 1});
  corner.update({&sb, 1});
  const LocalBox& b = sub.box;
  double vol = 0;
  for (int z = 0; z <= n + 1; ++z)
    for (int y = 0; y <= n + 1; ++y)
      for (int x = 0; x <= n + 1; ++x) {
        auto wrap = [&](int l, int a) { return ((l - 1 - shift[a]) % n + n) % n + 1; };
        const auto cb = static_cast<std::size_t>(b.index(x, y, z));
        const auto ca = static_cast<std::size_t>(b.index(wrap(x, 0), wrap(y, 1), wrap(z, 2)));
        ASSERT_NEAR(fb.d[cb], fa.d[ca], 1e-5) << "cell " << x << " " << y << " " << z;
        ASSERT_EQ(fb.body[cb], fa.body[ca]);
        vol += 1.0 - fb.d[cb];
      }
  EXPECT_GT(vol, 7 * 7 * 7);
}

TEST(Porosity, SubBoxesSeeTheWholeDomainField) {
  // Two uneven blocks along x (11 + 19 cells) see exactly the whole domain's field, ghosts
  // included, for a body across both the block boundary and the periodic boundary in y.
  const Shape s = test::sphere(5, 0.5);
  const int n = 30;
  const Subdomain all = test::whole(n);
  const BodyState st = state(3, Eigen::Vector3d(10.7, 1.2, 15.4));
  PorousField<double> fw;
  BodyField<double> whole({&s, 1}, all, test::unit_frame(), fw);
  whole.update({&st, 1});
  for (auto [off, cnt] : {std::pair{0, 11}, std::pair{11, 19}}) {
    const Subdomain part = test::subdomain({n, n, n}, {off, 0, 0}, {cnt, n, n});
    PorousField<double> fp;
    BodyField<double> bodies({&s, 1}, part, test::unit_frame(), fp);
    bodies.update({&st, 1});
    for (int z = 0; z <= n + 1; ++z)
      for (int y = 0; y <= n + 1; ++y)
        for (int x = 0; x <= cnt + 1; ++x) {
          const int gx = ((off + x - 1) % n + n) % n;  // global node of this local cell
          const auto cp = static_cast<std::size_t>(part.box.index(x, y, z));
          const auto cw = static_cast<std::size_t>(all.box.index(gx + 1, y, z));
          ASSERT_NEAR(fp.d[cp], fw.d[cw], 1e-5) << "block " << off << " cell " << x;
          ASSERT_EQ(fp.body[cp] >= 0, fw.body[cw] >= 0);
        }
  }
}

TEST(Porosity, TwoBodyRuleTakesTheMostSolidBody) {
  const Shape s = test::sphere(5, 0.5);
  const Subdomain sub = test::whole(32);
  PorousField<double> field;
  BodyField<double> bodies({&s, 1}, sub, test::unit_frame(), field);
  // Surfaces 0.6 cells apart: the porous bands overlap between the spheres.
  const BodyState st[2] = {state(7, Eigen::Vector3d(10.6, 16.2, 15.9)),
                           state(4, Eigen::Vector3d(21.2, 16.2, 15.9))};
  const UpdateStats stats = bodies.update(st);
  EXPECT_EQ(stats.interior_conflicts, 0u);
  const std::int32_t k7 = bodies.slot_of(7), k4 = bodies.slot_of(4);
  int shared = 0;
  for (CellIndex c = 0; c < sub.box.cells_with_ghosts(); ++c) {
    const float d7 = bodies.body_porosity(7, c), d4 = bodies.body_porosity(4, c);
    const float d = std::min(d7, d4);
    ASSERT_EQ(field.d[static_cast<std::size_t>(c)], d);
    const std::int32_t expected = d == 1.0f ? -1 : (d4 <= d7 ? k4 : k7);  // ties: smaller id
    ASSERT_EQ(field.body[static_cast<std::size_t>(c)], expected);
    shared += d7 < 1.0f && d4 < 1.0f;
  }
  std::printf("cells in both bands: %d\n", shared);
  EXPECT_GT(shared, 0);
}

// Links from a d = 0 cell to a d = 1 cell of a cube of edge 6 cells at 12 orientations.
long interior_fluid_links(PorosityLookup lookup) {
  long links = 0;
  const Shape s = test::cube(6, 0.5);
  const Subdomain sub = test::whole(20);
  const LocalBox& b = sub.box;
  for (int trial = 0; trial < 12; ++trial) {
    PorousField<double> field;
    BodyField<double> bodies({&s, 1}, sub, test::unit_frame(), field, lookup);
    const Eigen::Quaterniond q(Eigen::AngleAxisd(
        0.37 * trial, Eigen::Vector3d(std::sin(trial), 1, std::cos(trial)).normalized()));
    const BodyState st = state(0, Eigen::Vector3d(10 + 0.13 * trial, 10.4, 9.8), q);
    bodies.update({&st, 1});
    for (int z = 1; z <= 20; ++z)
      for (int y = 1; y <= 20; ++y)
        for (int x = 1; x <= 20; ++x) {
          const CellIndex c = b.index(x, y, z);
          if (field.d[static_cast<std::size_t>(c)] != 0.0f) continue;
          for (int i = 1; i < d3q19::Q; ++i) {
            const auto& e = d3q19::c[static_cast<std::size_t>(i)];
            links += field.d[static_cast<std::size_t>(c + b.shift(e[0], e[1], e[2]))] == 1.0f;
          }
        }
  }
  return links;
}

TEST(Porosity, NoSolidCellNeighboursPureFluid) {
  // The momentum exchange sums over band cells only; that is complete because a d = 0 cell
  // never has a d = 1 neighbour along a D3Q19 link.
  EXPECT_EQ(interior_fluid_links(PorosityLookup::trilinear), 0);
}

// The nearest lookup takes its stencil in the lattice frame, which keeps the same property.
TEST(Porosity, NoSolidCellNeighboursPureFluidWithNearestLookup) {
  EXPECT_EQ(interior_fluid_links(PorosityLookup::nearest), 0);
}

// The stencil spacing dx / 2 must be a whole number of voxels (two with the scenes' lattice of
// dx / 4, one with voxels of dx / 2); anything else is refused at construction, naming the shape.
TEST(Porosity, StencilSpacingMustBeWholeVoxels) {
  const Subdomain sub = test::whole(16);
  for (double h : {0.5, 0.25}) {
    Shape s = test::sphere(3, 0.5);
    s.voxels.h = h;
    s.voxels.origin *= h / 0.25;
    PorousField<double> field;
    EXPECT_NO_THROW(BodyField<double>({&s, 1}, sub, test::unit_frame(), field)) << h;
  }
  Shape s = test::sphere(3, 0.5);
  s.voxels.h = 0.3;
  PorousField<double> field;
  try {
    BodyField<double> bodies({&s, 1}, sub, test::unit_frame(), field);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("shape 'sphere'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("whole number"), std::string::npos) << e.what();
  }
}

// Nearest voxel (the paper's lookup): the embedded volume converges like the trilinear one's
// and the band (0 < d < 1) is narrower.
TEST(Porosity, NearestLookupHasTheVolumeAndANarrowerBand) {
  for (double radius : {3.0, 6.0, 12.0}) {
    const int n = static_cast<int>(2 * radius) + 8;
    const Shape s = test::sphere(radius, 0.5);
    const Subdomain sub = test::whole(n);
    const BodyState st = state(0, Eigen::Vector3d(n / 2.0 + 0.31, n / 2.0 - 0.17, n / 2.0 + 0.05));
    PorousField<double> tri, near;
    BodyField<double> a({&s, 1}, sub, test::unit_frame(), tri, PorosityLookup::trilinear);
    BodyField<double> b({&s, 1}, sub, test::unit_frame(), near, PorosityLookup::nearest);
    const std::size_t band_tri = a.update({&st, 1}).band;
    const std::size_t band_near = b.update({&st, 1}).band;
    const double exact = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
    const double err = std::abs(solid_volume(sub, near) - exact) / exact;
    std::printf(
        "sphere R = %4.1f cells, nearest lookup: volume error %.4f %%, band %zu cells "
        "(trilinear %zu, ratio %.3f)\n",
        radius, 100 * err, band_near, band_tri, double(band_near) / double(band_tri));
    EXPECT_LT(err, 0.02);
    EXPECT_LT(band_near, band_tri);
  }
}

TEST(Porosity, SiStatesAreConvertedWithTheUnitConverterAndOrigin) {
  // The same body given in SI with dx = 2 mm and an origin at (-1, 0, 2) m lands on the same
  // cells with the same porosity as in lattice units.
  const double dx = 2e-3;
  Shape si = test::sphere(4 * dx, dx / 2);
  const Shape lat = test::sphere(4, 0.5);
  const Subdomain sub = test::whole(16);
  LatticeFrame frame;
  frame.origin = Eigen::Vector3d(-1, 0, 2);
  frame.units = UnitConverter::from_tau(dx, 0.8, 1e-6, 1000);
  PorousField<double> fs, fl;
  BodyField<double> bs({&si, 1}, sub, frame, fs);
  BodyField<double> bl({&lat, 1}, sub, test::unit_frame(), fl);
  const Eigen::Vector3d x(8.3, 7.9, 8.1);
  const Eigen::Vector3d v(0.01, -0.02, 0.03), w(0.001, 0.002, -0.003);
  const BodyState ss =
      state(0, frame.origin + dx * x, {1, 0, 0, 0}, v * frame.units.velocity(), w / frame.units.dt);
  const BodyState sl = state(0, x, {1, 0, 0, 0}, v, w);
  bs.update({&ss, 1});
  bl.update({&sl, 1});
  for (std::size_t c = 0; c < fs.d.size(); ++c) ASSERT_NEAR(fs.d[c], fl.d[c], 1e-5);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(fs.bodies[0].centre[a], x[a], 1e-9);
    EXPECT_NEAR(fs.bodies[0].velocity[a], v[a], 1e-12);
    EXPECT_NEAR(fs.bodies[0].omega[a], w[a], 1e-12);
  }
  EXPECT_TRUE(fs.active);
  bs.update({});
  EXPECT_FALSE(fs.active);
  for (std::size_t c = 0; c < fs.d.size(); ++c) ASSERT_EQ(fs.d[c], 1.0f);
}

}  // namespace
}  // namespace lbdem::hlbm

namespace lbdem::hlbm {
namespace {

TEST(Porosity, ReachBoundsThePorousSupport) {
  // Every node with d < 1 lies within reach() of the centre, and reach() is tight enough
  // for routing (less than two cells beyond the surface).
  const Shape s = test::cube(8, 0.5);
  const Subdomain sub = test::whole(24);
  PorousField<double> field;
  BodyField<double> bodies({&s, 1}, sub, test::unit_frame(), field);
  const Eigen::Vector3d x(12.3, 11.8, 12.1);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 1, 1).normalized()));
  const BodyState st = test::state(0, x, q);
  bodies.update({&st, 1});
  double farthest = 0;
  for (int z = 0; z <= 25; ++z)
    for (int y = 0; y <= 25; ++y)
      for (int xx = 0; xx <= 25; ++xx)
        if (field.d[static_cast<std::size_t>(sub.box.index(xx, y, z))] < 1.0f)
          farthest = std::max(
              farthest,
              (Eigen::Vector3d(sub.position(0, xx), sub.position(1, y), sub.position(2, z)) - x)
                  .norm());
  std::printf("farthest porous node %.3f cells, reach %.3f, half diagonal %.3f\n", farthest,
              bodies.reach(0), 4 * std::sqrt(3.0));
  EXPECT_LE(farthest, bodies.reach(0));
  EXPECT_LT(bodies.reach(0), 4 * std::sqrt(3.0) + 2.0);
}

// Ties of the nearest lookup: a sphere voxelized as the catalogue does it (SI spacing
// h = dx / 2, lattice centred on the sphere) with an even voxel count, centred between nodes or
// on a node, puts every stencil point of every node on a voxel face. The lookup must read such a
// pose as one side of the tie for every point: the same field as the body moved by 1e-7 cells
// (round half up sends ties to the upper voxel, which is the pose just below the tie). Before
// the tie tolerance, the round-off of the map into the reference lattice sent the points below
// the centre down and those above it up: the outlier of the issue (phi 0.343, 32 cells per
// period, d = 27.7 cells) embedded 5 % less volume and its Stokes drag read 16 % low.
TEST(Porosity, NearestLookupReadsATiePoseAsOneSide) {
  int ties = 0;
  for (const double dx : {1.6e-3 / 32, 1.6e-3 / 13, 1e-4})
    for (double radius = 3.0; radius <= 14.0; radius += 0.9) {
      const double r = (radius == 3.0 && dx == 1.6e-3 / 32) ? 13.842850996 : radius;  // outlier
      Voxels vox = voxelize(SolidGeometry::sphere(r * dx), 0.5 * dx, 2);
      if (vox.n[0] % 2 != 0) continue;  // odd: stencil points on voxel centres, no ties
      Shape s;
      s.voxels = std::move(vox);
      s.bounding_radius = r * dx;
      const int n = 2 * static_cast<int>(std::ceil(r)) + 8;
      const Subdomain sub = test::whole(n);
      LatticeFrame frame;
      frame.units = UnitConverter::from_tau(dx, 0.8, 1e-6, 1000);
      for (const double centre : {n / 2.0, n / 2.0 + 0.5}) {  // between nodes, on a node
        PorousField<double> tie, side;
        BodyField<double> a({&s, 1}, sub, frame, tie, PorosityLookup::nearest);
        BodyField<double> b({&s, 1}, sub, frame, side, PorosityLookup::nearest);
        const BodyState at = state(0, Eigen::Vector3d::Constant(centre * dx));
        const BodyState below = state(0, Eigen::Vector3d::Constant((centre - 1e-7) * dx));
        a.update({&at, 1});
        b.update({&below, 1});
        std::size_t differ = 0;
        for (std::size_t c = 0; c < tie.d.size(); ++c) differ += tie.d[c] != side.d[c];
        const double volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
        const double err = solid_volume(sub, tie) / volume - 1;
        EXPECT_EQ(differ, 0u) << "dx " << dx << " radius " << r << " cells, centre " << centre
                              << ": " << differ << " cells differ, volume error " << err;
        EXPECT_LT(std::abs(err), 0.02) << "dx " << dx << " radius " << r << " centre " << centre;
        ++ties;
      }
    }
  std::printf("%d tie poses of spheres with an even voxel count read as one side\n", ties);
  EXPECT_GT(ties, 20);
}

}  // namespace
}  // namespace lbdem::hlbm
