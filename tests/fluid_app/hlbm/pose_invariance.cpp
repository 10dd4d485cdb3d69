// Pose invariance of the loads on a fixed body, as a property (docs/validation.md
// section 7). One body held in place in a triply periodic box (a simple cubic array), on the
// real solver and the real shape catalogue's voxelization (SI spacing h = dx / 2, the calibrated
// hydrodynamic radius of the scene defaults, the nearest lookup):
// * drag: a uniform body force on the fluid; at steady state K = F / (6 pi mu a U), U the
//   superficial velocity, a the radius (of the volume-equivalent sphere for a cube);
// * torque: no force, the body spinning in place at Omega; at steady state T / (8 pi mu a^3 Omega).
// The same body at 16 poses must feel the same load: (max - min) / mean <= 2 %, and the mean
// must lie within the case's tolerance of its reference. The poses: the body centred between
// nodes, on a node, a quarter cell off and at (0.3, 0.2, 0.1) cells, all four unrotated (the
// poses scenes start from, and those where every stencil point of the nearest lookup can sit
// on a voxel face), then 12 random sub-cell offsets with random orientations (fixed seed).
//
// Each case is one test (ctest pose_invariance_*, label validation); a case prints every pose.
// POSE_CASE="sphere|cube drag|spin n size_cells tau reference" runs any other case through
// PoseInvariance.Measure (the commands of docs/validation.md section 7), POSE_LOOKUP=trilinear
// with the other lookup (and its calibrated offset).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "coupler_lib/geometry/build_shape.hpp"
#include "coupler_lib/scene/band_calibration.hpp"
#include "fluid_app/coupling/solver_binding.hpp"
#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"
#include "tests/fluid_app/hlbm/hlbm_fixtures.hpp"

namespace lbdem::hlbm {
namespace {

// The box in SI units, as the programs see a scene (a 1.6 mm box of water): the map into the
// reference lattice then carries the round-off it has in a run.
constexpr double kBox = 1.6e-3, kNu = 1e-6, kRho = 1000;

// Sangani & Acrivos 1982, Eq. 60 / Table 1 (tools/lbdem/references.py): K of a simple cubic
// array of spheres.
double sangani_acrivos_k(double phi) {
  static constexpr std::array<double, 31> alpha = {
      1.000000,  1.418649,  2.012564,   2.331523,  2.564809, 2.584787, 2.873609, 3.340163,
      3.536763,  3.504092,  3.253622,   2.689757,  2.037769, 1.809341, 1.877347, 1.534685,
      0.9034708, 0.2857896, -0.5512626, -1.278724, 1.013350, 5.492491, 4.615388, -0.5736023,
      -2.865924, -4.709215, -6.870076,  0.1455304, 12.51891, 9.742811, -5.566269};
  const double chi = std::cbrt(phi / (std::numbers::pi / 6));
  double k = 0, power = 1;
  for (const double a : alpha) {
    k += a * power;
    power *= chi;
  }
  return k;
}

enum class Load { drag, spin };

struct Case {
  std::string kind;  // sphere | cube
  Load load = Load::drag;
  int n = 16;       // box edge, cells
  double size = 8;  // diameter or edge, cells
  double tau = 0.8;
  double reference = 0;         // K (drag) or T / (8 pi mu a^3 Omega) (spin); 0: none (spread only)
  double tolerance = 0;         // of the mean against the reference
  double per_pose = 0;          // > 0: every pose within this of the reference as well
  bool spread_asserted = true;  // (max - min) / mean <= 2 %
  // Band offset in cells (the surface moved inward by it); NaN: the calibrated rule's.
  double offset_cells = std::numeric_limits<double>::quiet_NaN();
  PorosityLookup lookup = PorosityLookup::nearest;  // fluid.porosity_lookup
};

struct Pose {
  Eigen::Vector3d offset;  // cells, from the box centre (between nodes)
  Eigen::Quaterniond q;
};

std::vector<Pose> poses() {
  const Eigen::Quaterniond id(1, 0, 0, 0);
  std::vector<Pose> out = {{Eigen::Vector3d::Zero(), id},
                           {Eigen::Vector3d::Constant(0.5), id},
                           {Eigen::Vector3d::Constant(0.25), id},
                           {Eigen::Vector3d(0.3, 0.2, 0.1), id}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(0, 1);
  std::normal_distribution<double> normal;
  while (out.size() < 16) {
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    q.normalize();
    out.push_back({Eigen::Vector3d(uni(rng), uni(rng), uni(rng)), q});
  }
  return out;
}

// Radius of the sphere (of the volume-equivalent sphere for a cube), cells.
double radius(const Case& c) {
  return c.kind == "sphere" ? c.size / 2 : c.size * std::cbrt(3 / (4 * std::numbers::pi));
}

// The surface's offset in cells: the case's, or the calibrated rule's for the case's lookup.
double band_offset_cells(const Case& c) {
  return std::isnan(c.offset_cells) ? *band_radius_excess_cells(c.tau, c.lookup) : c.offset_cells;
}

// The shape as the scene catalogue builds it for the fluid (coupler_lib/scene/shape_catalogue.cpp).
Shape make_shape(const Case& c, double dx) {
  ShapeParams p;
  p.name = c.kind;
  p.kind = value_of(kShapeKindWords, c.kind);
  p.size = c.size * dx;
  const double e = c.kind == "sphere" ? p.size / 2 : p.size;
  p.extents = {e, e, e};
  p.clump.source = ClumpSource::fill;
  p.clump.spheres = 1;  // the clump plays no part here
  p.hydrodynamic_offset = band_offset_cells(c) * dx;
  return build_shape(p, 0.5 * dx);
}

// The sphere's hydrodynamic radius a_h in cells (Ladd 1994): the radius at which an exact sphere
// in the same array would feel the measured K, K_SA(phi(a_h)) a_h / a = K, by bisection (the
// left side grows with a_h). The measure behind the band calibration (tools/calibrate_band.py).
double hydrodynamic_radius_cells(const Case& c, double k) {
  const double a = radius(c), cells = double(c.n) * c.n * c.n;
  double lo = 0.5 * a, hi = 1.5 * a;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double phi = 4 * std::numbers::pi * mid * mid * mid / (3 * cells);
    (sangani_acrivos_k(phi) * mid / a < k ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Result {
  double value = 0;  // K or T / (8 pi mu a^3 Omega)
  double arm = 0;    // drag: |T| / |F| (cells), the lever arm of the load about the centre
  int steps = 0;
};

// Steps until the load and the flow are steady (relative change below 1e-5 over a check
// interval of n^2 / 16 steps, which leaves about 1e-4; for the drag also the load within 1e-4
// of the force on the box).
// The case's lattice in SI units (the parameters of a scene with that box).
FluidParams lattice(const Case& c) {
  FluidParams p = testing_fluid::lattice_params(c.n, c.n, c.n, c.tau);
  p.dx = kBox / c.n;
  p.domain = {kBox, kBox, kBox};
  p.viscosity = kNu;
  p.density = kRho;
  p.units = UnitConverter::from_tau(p.dx, c.tau, kNu, kRho);
  return p;
}

// The solver carries the steady flow of the previous pose into the next one (a new body field on
// the same populations): Stokes flow has one steady state, which the next pose then reaches
// from close by, 2-4 times sooner than from rest.
Result steady_load(const Case& c, FluidSolver<double>& s, const Shape& shape, const Pose& pose) {
  const int n = c.n;
  const FluidParams p = lattice(c);
  BodyField<double> bodies({&shape, 1}, subdomain_of(s, p), {Eigen::Vector3d::Zero(), p.units},
                           s.porous(), c.lookup);
  PenaltyLoads<double> loads;
  const double nu = (c.tau - 0.5) / 3.0;  // lattice
  const double a = radius(c);
  const double cells = double(n) * n * n;
  // Lattice speeds about 1e-4 (Re ~ 0.01): a body force for U ~ 1e-4 at the reference drag, or
  // an equator speed of 1e-4.
  const double g = c.load == Load::drag
                       ? 6 * std::numbers::pi * nu * a * 1e-4 * std::max(c.reference, 1.0) / cells
                       : 0.0;
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  if (c.load == Load::spin) omega = Eigen::Vector3d(0.3, -0.4, 0.866).normalized() * (1e-4 / a);
  s.set_uniform_force({0, 0, g});
  const BodyState st = test::state(0, Eigen::Vector3d::Constant(kBox / 2) + pose.offset * p.dx,
                                   pose.q, Eigen::Vector3d::Zero(), omega / p.units.dt);
  bodies.update({&st, 1});
  std::vector<double> rho, u;
  const int check = std::max(20, n * n / 16);
  double last = 0;
  Result r;
  for (int k = 0; k < 100000; ++k) {
    s.step();
    const BodyLoad l = loads.loads(bodies, k).at(0);
    bodies.update({&st, 1});
    if ((k + 1) % check != 0) continue;
    Eigen::Vector3d f, t;
    for (int i = 0; i < 3; ++i) {
      f[i] = l.f[i] / p.units.force();
      t[i] = l.t[i] / p.units.torque();
    }
    double now = 0;
    bool steady = false;
    if (c.load == Load::drag) {
      s.macroscopic(rho, u);
      double sum = 0;
      for (std::size_t i = 2; i < u.size(); i += 3) sum += u[i];
      now = sum / cells;
      steady =
          std::abs(now - last) < 1e-5 * std::abs(now) && std::abs(f.z() / (g * cells) - 1) < 1e-4;
      r.value = f.z() / (6 * std::numbers::pi * nu * a * now);
      r.arm = t.norm() / std::abs(f.z());
    } else {
      now = -t.dot(omega.normalized());
      steady = std::abs(now - last) < 1e-5 * std::abs(now);
      r.value = now / (8 * std::numbers::pi * nu * a * a * a * omega.norm());
    }
    if (steady) {
      r.steps = k + 1;
      return r;
    }
    last = now;
  }
  ADD_FAILURE() << "no steady state after 100000 steps";
  return r;
}

void check_case(const Case& c) {
  const auto t0 = std::chrono::steady_clock::now();
  const Shape shape = make_shape(c, kBox / c.n);
  const char* what = c.load == Load::drag ? "K" : "T / (8 pi mu a^3 Omega)";
  std::printf("%s %s, %.2f cells across in a box of %d (phi %.3f), tau %.2f, %d voxels across\n",
              c.kind.c_str(), c.load == Load::drag ? "drag" : "spin", c.size, c.n,
              (c.kind == "sphere" ? std::numbers::pi / 6 : 1.0) * std::pow(c.size / c.n, 3), c.tau,
              shape.voxels.n[0]);
  std::vector<double> values;
  // Sphere drag: a_h - a per pose, and the band's own excess a_h - a + offset (what the
  // calibration must remove; docs/method.md "Hydrodynamic radius calibration").
  const bool radius_excess = c.kind == "sphere" && c.load == Load::drag;
  double mean_excess = 0;  // summed, then divided
  FluidSolver<double> solver(lattice(c), MPI_COMM_SELF);
  for (const Pose& p : poses()) {
    const Result r = steady_load(c, solver, shape, p);
    values.push_back(r.value);
    std::printf("  offset (%.3f, %.3f, %.3f) q (%+.3f, %+.3f, %+.3f, %+.3f): %s = %.5f",
                p.offset.x(), p.offset.y(), p.offset.z(), p.q.w(), p.q.x(), p.q.y(), p.q.z(), what,
                r.value);
    if (c.reference > 0) std::printf(" (%+.2f %%)", 100 * (r.value / c.reference - 1));
    if (c.load == Load::drag) std::printf(", lever arm %.3f cells", r.arm);
    if (radius_excess) {
      const double excess = hydrodynamic_radius_cells(c, r.value) - radius(c);
      mean_excess += excess;
      std::printf(", a_h - a %+.4f cells", excess);
    }
    std::printf(", %d steps\n", r.steps);
    std::fflush(stdout);
    if (c.per_pose > 0) {
      EXPECT_LT(std::abs(r.value / c.reference - 1), c.per_pose)
          << "offset " << p.offset.transpose() << " q " << p.q.coeffs().transpose();
    }
  }
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  double mean = 0;
  for (const double v : values) mean += v / values.size();
  const double spread = (*hi - *lo) / mean;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s over %zu poses: mean %.5f", what, values.size(), mean);
  if (c.reference > 0)
    std::printf(" (reference %.4f, %+.2f %%, tolerance %g %%)", c.reference,
                100 * (mean / c.reference - 1), 100 * c.tolerance);
  std::printf(", (max - min) / mean %.2f %% (bound 2 %%), %.1f s\n", 100 * spread, wall);
  mean_excess /= values.size();
  if (radius_excess)
    std::printf(
        "a_h - a over %zu poses: mean %+.4f cells with offset %+.4f cells: band excess %+.4f "
        "cells\n",
        values.size(), mean_excess, band_offset_cells(c), mean_excess + band_offset_cells(c));
  // The lines docs/validation-table.md is generated from (tools/validation_table.py).
  const char* name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  if (c.spread_asserted)
    std::printf(
        "[validation] %s: spread over %zu poses error %.3e, tolerance %.1e (run time %.2f s, "
        "1 rank)\n",
        name, values.size(), spread, 0.02, wall);
  if (c.reference > 0)
    std::printf(
        "[validation] %s: mean %s against the reference error %.3e, tolerance %.1e (run "
        "time %.2f s, 1 rank)\n",
        name, what, std::abs(mean / c.reference - 1), c.tolerance, wall);
  std::fflush(stdout);
  if (c.spread_asserted) {
    EXPECT_LE(spread, 0.02);
  }
  if (c.reference > 0) {
    EXPECT_LE(std::abs(mean / c.reference - 1), c.tolerance);
  }
}

double phi_of(const Case& c) {
  return (c.kind == "sphere" ? std::numbers::pi / 6 : 1.0) * std::pow(c.size / c.n, 3);
}

Case sphere_in_array(Load load, int n, double phi, double tau) {
  Case c;
  c.kind = "sphere";
  c.load = load;
  c.n = n;
  c.size = 2 * n * std::cbrt(3 * phi / (4 * std::numbers::pi));
  c.tau = tau;
  if (load == Load::drag) c.reference = sangani_acrivos_k(phi_of(c));
  return c;
}

// Dilute array, d = 11.5 cells (phi 0.1, tau 1): centred between nodes its 28 voxels put every
// stencil point on a voxel face, and before the tie tolerance the round-off split the ties
// (K -19.5 % there). Measured (docs/validation.md section 7): mean -1.67 %, spread 0.60 %;
// tolerance 3 % (1.8x).
TEST(PoseInvariance, SphereDragDiluteD12Tau1) {
  Case c = sphere_in_array(Load::drag, 20, 0.1, 1.0);
  c.tolerance = 0.03;
  check_case(c);
}

// The same at tau 0.8 (d = 12.1 cells, 28 voxels, ties split before the fix).
TEST(PoseInvariance, SphereDragDiluteD12Tau08) {
  Case c = sphere_in_array(Load::drag, 21, 0.1, 0.8);
  c.tolerance = 0.03;
  check_case(c);
}

// The outlier: phi 0.343, 32 cells per period (d = 27.8 cells, 60 voxels), tau 0.8;
// centred, K read 12.96 before the tie tolerance (-16 % against Zick & Homsy's 15.4). Every pose
// and the mean must read within 5 % of Zick & Homsy (Sangani & Acrivos's series: 15.53).
TEST(PoseInvariance, SphereDragDenseD28Phi0343) {
  Case c = sphere_in_array(Load::drag, 32, 0.343, 0.8);
  c.reference = 15.4;  // Zick & Homsy 1982, phi 0.343
  c.tolerance = 0.05;
  c.per_pose = 0.05;
  check_case(c);
}

// Dense arrays at few cells per gap, where the mean is a resolution error and the spread is what
// is asserted (the reference 0: K printed, not judged). phi 0.3 with d = 11.6 cells (2.4-cell
// gaps): K 10.869, -10.2 % against Sangani & Acrivos (12.099), spread 1.15 %. phi 0.45 with
// d = 30.4 cells (1.6-cell gaps): K 27.149, -9.6 % against their series' 30.03 (which the
// reference data call unreliable near close packing), spread 0.43 %.
Case spread_only(Case c) {
  c.reference = 0;
  return c;
}

TEST(PoseInvariance, SphereDragDensePhi03D12) {
  check_case(spread_only(sphere_in_array(Load::drag, 14, 0.3, 0.8)));
}

TEST(PoseInvariance, SphereDragDensePhi045D30) {
  check_case(spread_only(sphere_in_array(Load::drag, 32, 0.45, 0.8)));
}

// The calibrated drag at two sizes (docs/method.md, "Hydrodynamic radius calibration"): a sphere
// in the size series' box of 2 d (phi 0.065) against Sangani & Acrivos, mean over 16 poses
// (tools/band_size_series.py runs the whole series). The spread is not asserted here (radius 3:
// 3-5 %); the cases above hold the bound at their sizes.
Case calibrated_sphere(double d, double tau, double tolerance) {
  Case c;
  c.kind = "sphere";
  c.n = int(2 * d);
  c.size = d;
  c.tau = tau;
  c.reference = sangani_acrivos_k(phi_of(c));
  c.tolerance = tolerance;
  c.spread_asserted = false;
  return c;
}

// Radius 6 cells: measured -0.57 % (tau 0.6) and -0.81 % (tau 1); tolerance 1 % and 1.5 %
// (1.75x, 1.85x).
TEST(PoseInvariance, CalibratedR6Tau06) {
  check_case(calibrated_sphere(12, 0.6, 0.01));
}

TEST(PoseInvariance, CalibratedR6Tau1) {
  check_case(calibrated_sphere(12, 1.0, 0.015));
}

// Radius 3 cells, KNOWN OFF (disabled; ctest pose_invariance_known_off_CalibratedR3Tau06 and
// ..._CalibratedR3Tau1 run them and check the printed mean lies in its recorded band): the rule,
// one offset per tau for every size, over-erodes a small sphere, whose band holds less excess
// (a_h - a = a(tau) + b(tau) / R, b < 0); measured -4.72 % and -6.53 % against the tolerances
// of radius 6. The size term that removes it moves three settling validations out of their
// tolerances (docs/method.md).
TEST(PoseInvariance, DISABLED_CalibratedR3Tau06) {
  check_case(calibrated_sphere(6, 0.6, 0.01));
}

TEST(PoseInvariance, DISABLED_CalibratedR3Tau1) {
  check_case(calibrated_sphere(6, 1.0, 0.015));
}

// Spinning sphere (the torque path), d = 8 cells in a box of 4 d as coupled_sphere_spin:
// T against Stokes' 8 pi mu a^3 Omega, tolerance 5 % (that test's). The case that chose the
// reference lattice (shape.hpp): with voxels of dx/2 each stencil point moves by up to dx/4 to
// its voxel's centre, all by the same amount when the body is not turned, and the spread is
// 2.94 %; voxels of dx/4 holding box fills bound the move by dx/8 (docs/validation.md
// section 7).
TEST(PoseInvariance, SphereSpinD8) {
  Case c = sphere_in_array(Load::spin, 32, 0.0082, 0.8);
  c.size = 8;
  c.reference = 1.0;
  c.tolerance = 0.05;
  check_case(c);
}

// Cube of edge 8 cells in a box of 40 (phi 0.008, tau 1): no published drag for a cubic array
// of cubes, so the spread alone is asserted. The box is five edges wide because at three (box
// 24) the array's images make K depend on how the cube is turned by about 2 % (the same 12
// rotated poses spread 2.0 % there and 0.45 % here; docs/validation.md section 7), which is the
// array's physics, not the lattice's. With voxels of dx/2 instead of the reference lattice's
// dx/4 the spread is 2.65 %: unrotated, K moves with where the faces fall between node planes.
TEST(PoseInvariance, CubeDragDiluteD8) {
  Case c;
  c.kind = "cube";
  c.n = 40;
  c.size = 8;
  c.tau = 1.0;
  check_case(c);
}

// Any case from the environment, for the measurements of docs/validation.md section 7 and of
// the band calibration (tools/band_size_series.py):
// POSE_CASE="sphere drag 32 27.79 0.8 15.4" (kind, load, box, size in cells, tau, reference or
// 0), optionally followed by the band offset in cells (default: the calibrated rule's);
// POSE_LOOKUP=nearest|trilinear (default nearest).
TEST(PoseInvariance, Measure) {
  const char* env = std::getenv("POSE_CASE");
  if (env == nullptr) GTEST_SKIP() << "set POSE_CASE to measure a case";
  char kind[16], load[16];
  Case c;
  const int read = std::sscanf(env, "%15s %15s %d %lf %lf %lf %lf", kind, load, &c.n, &c.size,
                               &c.tau, &c.reference, &c.offset_cells);
  ASSERT_GE(read, 6) << "POSE_CASE: kind load box size tau reference [offset]";
  c.kind = kind;
  c.load = std::string(load) == "spin" ? Load::spin : Load::drag;
  c.tolerance = 1.0;
  if (const char* lookup = std::getenv("POSE_LOOKUP")) {
    const auto l = find_word(kPorosityLookupWords, lookup);
    ASSERT_TRUE(l.has_value()) << "POSE_LOOKUP: nearest or trilinear, got '" << lookup << "'";
    c.lookup = *l;
  }
  check_case(c);
}

}  // namespace
}  // namespace lbdem::hlbm
