// The lubrication law (dem_app/lubrication/lubrication_law.hpp) and the dem.lubrication scene keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/lubrication/lubrication.hpp"
#include "dem_app/lubrication/lubrication_law.hpp"
#include "dem_app/setup/dem_setup.hpp"

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

TEST(LubricationLaw, ZeroBeyondTheCutoffContinuousAtItSaturatedBelowTheMinimumOffInContact) {
  const double a = 1e-3;
  EXPECT_EQ(lubrication_resistance(kLaw, a, a, kLaw.cutoff), 0.0);
  EXPECT_EQ(lubrication_resistance(kLaw, a, a, 2 * kLaw.cutoff), 0.0);
  const double just_below = lubrication_resistance(kLaw, a, a, kLaw.cutoff * (1 - 1e-9));
  EXPECT_GT(just_below, 0.0);
  EXPECT_LT(just_below, 1e-8 * lubrication_resistance(kLaw, a, a, 0.5 * kLaw.cutoff));
  const double at_min = lubrication_resistance(kLaw, a, 0.0, kLaw.min_gap);
  EXPECT_EQ(lubrication_resistance(kLaw, a, 0.0, 0.1 * kLaw.min_gap), at_min);
  // Off once the surfaces touch: the DEM contact alone acts there (lubrication_law.hpp).
  EXPECT_EQ(lubrication_resistance(kLaw, a, 0.0, 0.0), 0.0);
  EXPECT_EQ(lubrication_resistance(kLaw, a, 0.0, -1e-5), 0.0);
  EXPECT_EQ(lubrication_resistance(kLaw, a, a, -1e-5), 0.0);
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
  EXPECT_EQ(wall_sliding_resistance(law, a, 0.3 * law.min_gap).coupling,
            wall_sliding_resistance(law, a, law.min_gap).coupling);
  for (double g : {0.0, -1e-6}) {  // in contact: off
    const SlidingResistance c = wall_sliding_resistance(law, a, g);
    EXPECT_EQ(c.translation, 0.0);
    EXPECT_EQ(c.coupling, 0.0);
    EXPECT_EQ(c.rotation, 0.0);
  }
  EXPECT_GT(s.translation * s.rotation, s.coupling * s.coupling);
  EXPECT_GT(wall_sliding_resistance(law, a, 2e-6).translation, s.translation);
}

// Jeffrey & Onishi (1984): the log coefficients of Y^A (1/6), Y^B (-1/4) and Y^C (1/5 and the
// cross term 1/20) for equal spheres, and the wall's 8/15, 2/15, 2/5 as the second sphere grows.
TEST(LubricationLaw, PairSlidingCoefficientsOfEqualSpheresAndTheWallLimit) {
  const LubricationLaw law{2e-3, 1e-4, 1e-6};
  const double a = 1e-3, mu = law.viscosity, h = 1e-5;
  const double l = std::log(law.cutoff / h), s = 2 * a / (2 * a + h);
  const PairSlidingResistance r = pair_sliding_resistance(law, a, a, h);
  EXPECT_NEAR(r.translation, 6 * kPi * mu * a / 6 * l * s * s, 1e-15);
  EXPECT_NEAR(r.coupling1, -4 * kPi * mu * a * a / 4 * l * s, 1e-18);
  EXPECT_DOUBLE_EQ(r.coupling2, r.coupling1);
  EXPECT_NEAR(r.rotation11, 8 * kPi * mu * a * a * a / 5 * l, 1e-21);
  EXPECT_DOUBLE_EQ(r.rotation22, r.rotation11);
  EXPECT_NEAR(r.rotation12, kPi * mu * 8 * a * a * a / 20 * l, 1e-21);
  // A sphere 1e6 times larger: the plane wall's coefficients (coupling: same size, and the sign
  // of d x w against w x n, lubrication_law.hpp).
  const SlidingResistance w = wall_sliding_resistance(law, a, h);
  const PairSlidingResistance big = pair_sliding_resistance(law, a, 1e6 * a, h);
  EXPECT_NEAR(big.translation / w.translation, 1.0, 1e-5);
  EXPECT_NEAR(-big.coupling1 / w.coupling, 1.0, 1e-5);
  EXPECT_NEAR(big.rotation11 / w.rotation, 1.0, 1e-5);
  // Zero at and beyond h_c and in contact; held below h_min (the rotations exactly, the
  // translation and couplings up to the distance factor s).
  EXPECT_EQ(pair_sliding_resistance(law, a, a, law.cutoff).translation, 0.0);
  EXPECT_EQ(pair_sliding_resistance(law, a, 2 * a, 2 * law.cutoff).rotation12, 0.0);
  const PairSlidingResistance at_min = pair_sliding_resistance(law, a, 2 * a, law.min_gap);
  for (double g : {0.3 * law.min_gap, 1e-3 * law.min_gap}) {
    const PairSlidingResistance r2 = pair_sliding_resistance(law, a, 2 * a, g);
    EXPECT_EQ(r2.rotation11, at_min.rotation11);
    EXPECT_EQ(r2.rotation12, at_min.rotation12);
    const double ratio = (3 * a + g) / (3 * a + law.min_gap);  // 1 / s relative to h_min
    EXPECT_NEAR(r2.translation * ratio * ratio / at_min.translation, 1.0, 1e-13);
    EXPECT_NEAR(r2.coupling2 * ratio / at_min.coupling2, 1.0, 1e-13);
  }
  for (double g : {0.0, -1e-6}) {  // in contact: off
    const PairSlidingResistance c = pair_sliding_resistance(law, a, 2 * a, g);
    EXPECT_EQ(c.translation, 0.0);
    EXPECT_EQ(c.coupling1, 0.0);
    EXPECT_EQ(c.rotation12, 0.0);
  }
}

// The pair's sliding loads only dissipate, conserve angular momentum about any point
// (T1 + T2 + (x1 - x2) x F1 = 0 with F2 = -F1), and vanish for a rigid rotation of the pair.
TEST(LubricationLaw, PairSlidingDissipatesAndConservesAngularMomentum) {
  const LubricationLaw law{2e-3, 1e-4, 1e-6};
  const double a1 = 1e-3;
  std::uint64_t seed = 12345;
  auto random = [&seed] {  // in [-1, 1)
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(seed >> 11) * 0x1.0p-52 - 1.0;
  };
  auto random_vector = [&](double scale) {
    return Vec3{scale * random(), scale * random(), scale * random()};
  };
  for (double beta : {0.1, 0.5, 1.0, 3.0, 40.0})
    for (double gap : {2e-7, 5e-7, 1e-5, 6e-5}) {
      const double a2 = beta * a1, r = a1 + a2 + gap;
      const PairSlidingResistance res = pair_sliding_resistance(law, a1, a2, gap);
      for (int trial = 0; trial < 20; ++trial) {
        Vec3 d = random_vector(1.0);
        const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (double& x : d) x /= norm;
        const Vec3 du = random_vector(1e-2), w1 = random_vector(10.0), w2 = random_vector(10.0);
        const PairSlidingLoads l = pair_sliding_loads(res, d, du, w1, w2);
        double power = 0, scale = 0;
        for (int k = 0; k < 3; ++k) {
          power -= l.force1[k] * du[k] + l.torque1[k] * w1[k] + l.torque2[k] * w2[k];
          scale += std::abs(l.force1[k] * du[k]) + std::abs(l.torque1[k] * w1[k]) +
                   std::abs(l.torque2[k] * w2[k]);
        }
        EXPECT_GE(power, -1e-12 * scale) << "beta " << beta << " gap " << gap;
        // x1 - x2 = -r d.
        const Vec3 moment{-r * (d[1] * l.force1[2] - d[2] * l.force1[1]),
                          -r * (d[2] * l.force1[0] - d[0] * l.force1[2]),
                          -r * (d[0] * l.force1[1] - d[1] * l.force1[0])};
        for (int k = 0; k < 3; ++k) {
          const double size = std::abs(l.torque1[k]) + std::abs(l.torque2[k]) + std::abs(moment[k]);
          EXPECT_NEAR(l.torque1[k] + l.torque2[k] + moment[k], 0.0, 1e-12 * size);
        }
        // Rigid rotation w of the pair: du = w x (x1 - x2) = -r w x d.
        const Vec3 rigid{-r * (w1[1] * d[2] - w1[2] * d[1]), -r * (w1[2] * d[0] - w1[0] * d[2]),
                         -r * (w1[0] * d[1] - w1[1] * d[0])};
        const PairSlidingLoads z = pair_sliding_loads(res, d, rigid, w1, w1);
        const PairSlidingLoads ref = pair_sliding_loads(res, d, rigid, w1, Vec3{});
        // Round-off relative to the size of the loads without the rigid part (all components:
        // one of them alone can be arbitrarily small).
        double force_size = 0, torque_size = 0;
        for (int k = 0; k < 3; ++k) {
          force_size += std::abs(ref.force1[k]);
          torque_size += std::abs(ref.torque1[k]);
        }
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(z.force1[k], 0.0, 1e-12 * force_size + 1e-300);
          EXPECT_NEAR(z.torque1[k], 0.0, 1e-12 * torque_size + 1e-300);
        }
      }
    }
}

// Two clump spheres of different bodies inside h_c, through Lubrication::apply: the forces on
// the two are opposite and the torques plus the moments of the forces sum to zero.
TEST(LubricationPairs, NewtonsThirdLawAndAngularMomentum) {
  const LubricationLaw law{1e-3, 2e-4, 1e-6};
  const double a1 = 1e-3, a2 = 1.5e-3;
  Lubrication lub(law, {0, 1}, {a1, a2}, {}, 1e-4);
  double x[2][3] = {{0.1, 0.2, 0.3},
                    {0.1 + 0.6 * (a1 + a2 + 5e-5), 0.2 + 0.8 * (a1 + a2 + 5e-5), 0.3}};
  double v[2][3] = {{0.01, -0.02, 0.005}, {-0.003, 0.004, 0.02}};
  double w[2][3] = {{3.0, -1.0, 2.0}, {-0.5, 4.0, 1.0}};
  double f[2][3] = {}, t[2][3] = {};
  double *xp[2] = {x[0], x[1]}, *vp[2] = {v[0], v[1]}, *wp[2] = {w[0], w[1]}, *fp[2] = {f[0], f[1]},
         *tp[2] = {t[0], t[1]};
  const std::int64_t tags[2] = {1, 2};
  lub.apply({2, 2, tags, xp, vp, fp, wp, tp});
  ASSERT_EQ(lub.pairs(), 1u);
  double fmax = 0, lmax = 0;
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(f[0][k], -f[1][k]);
    fmax = std::max(fmax, std::abs(f[0][k]));
  }
  EXPECT_GT(fmax, 0.0);
  for (int k = 0; k < 3; ++k) {
    const int p = (k + 1) % 3, q = (k + 2) % 3;
    const double total = t[0][k] + t[1][k] + (x[0][p] * f[0][q] - x[0][q] * f[0][p]) +
                         (x[1][p] * f[1][q] - x[1][q] * f[1][p]);
    lmax = std::max({lmax, std::abs(t[0][k]), std::abs(t[1][k])});
    EXPECT_NEAR(total, 0.0, 1e-12 * (lmax + fmax * 0.3));
  }
  EXPECT_GT(lmax, 0.0);
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
