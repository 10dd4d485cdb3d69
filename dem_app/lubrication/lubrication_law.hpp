#pragma once
#include <array>
// The squeeze-film (lubrication) resistance between two spheres, or a sphere and a plane, that
// a lattice cannot resolve once the gap is below about one cell (docs/lubrication.md).
//
// Near contact, the force resisting the relative normal motion U of two spheres of radii a1, a2
// at surface gap h is F = 6 pi mu a1 U lambda(h), with the two singular terms of the exact
// solution (Jeffrey & Onishi 1984, their X^A_11; Brenner 1961 and Cooley & O'Neill 1969 for the
// sphere-plane limit):
//   lambda(h) = g1 a1 / h + g2 ln(a1 / h) + O(1),
//   g1 = beta^2 / (1 + beta)^2,  g2 = beta (1 + 7 beta + beta^2) / (5 (1 + beta)^3),
// beta = a2 / a1. Equal spheres: g1 = 1/4, g2 = 9/40; a plane (beta -> infinity): g1 = 1,
// g2 = 1/5. The O(1) term is left out: it cancels in the correction below.
//
// The correction adds only what the lattice misses: lambda(max(h, h_min)) - lambda(h_c) for
// h < h_c, zero beyond (Nguyen & Ladd 2002; Kempe & Froehlich 2012). It is continuous at h_c,
// positive below it, held at its value at the roughness h_min for 0 < h < h_min, and zero once
// the surfaces touch (h <= 0): there the DEM contact begins and alone sets the collision, so its
// restitution is not damped by a film that is no longer there (docs/lubrication.md, "At
// contact"). The sliding parts below follow the same rule.

namespace lbdem {

struct LubricationLaw {
  double viscosity = 0;  // mu, Pa s
  double cutoff = 0;     // h_c, m
  double min_gap = 0;    // h_min, m
};

// Coefficients g1, g2 of lambda for radii a1 (the sphere the force acts on) and a2; a2 <= 0
// stands for a plane wall.
struct SqueezeCoefficients {
  double g1 = 0, g2 = 0;
};
SqueezeCoefficients squeeze_coefficients(double a1, double a2);

// lambda(h) of the two singular terms (dimensionless), h > 0.
double squeeze_lambda(const SqueezeCoefficients& g, double a1, double h);

// The correction's resistance c in N s/m: the force on sphere 1 is -c (v1 - v2) . n n, with n
// the unit normal from sphere 1 towards sphere 2 (or the wall). Zero for gap >= h_c and in
// contact (gap <= 0).
double lubrication_resistance(const LubricationLaw& law, double a1, double a2, double gap);

// Sliding and rolling next to a plane wall (Goldman, Cox & Brenner 1967; O'Neill & Stewartson
// 1967): the log-singular parts of the resistance of a sphere of radius a translating parallel
// to the wall (6 pi mu a 8/15 ln(a/h)), rotating about an axis parallel to it
// (8 pi mu a^3 2/5 ln(a/h)) and their coupling (6 pi mu a^2 2/15 ln(a/h) = 8 pi mu a^2 1/10
// ln(a/h), the same both ways by reciprocity), each minus its value at h_c, held at h_min and
// zero in contact like the normal part. With n the unit normal from the sphere towards the wall,
// U_t and W_t the velocity and angular velocity parallel to the wall, the correction's force and
// torque are
//   F = -translation U_t - coupling (W_t x n),   T = -coupling (n x U_t) - rotation W_t,
// which dissipates U.A.U + 2 coupling W.(n x U) + W.C.W >= 0 (8/15 x 2/5 > (2/15)^2 x 6/8).
// Rotation about the normal has no log singularity and is left to the lattice.
struct SlidingResistance {
  double translation = 0;  // N s/m
  double coupling = 0;     // N s
  double rotation = 0;     // N m s
};
SlidingResistance wall_sliding_resistance(const LubricationLaw& law, double a, double gap);

// Sliding and rolling of two spheres (Jeffrey & Onishi 1984, the near-contact forms of Y^A,
// Y^B and Y^C; O'Neill & Majumdar 1970): the log-singular parts, each minus its value at h_c,
// held at h_min and zero in contact. With beta = a2 / a1, L = ln(h_c / max(h, h_min)) and
//   gA = 4 beta (2 + beta + 2 beta^2) / (15 (1 + beta)^3),
//   gB(beta) = -beta (4 + beta) / (5 (1 + beta)^2),
//   gC(beta) = 2 beta / (5 (1 + beta)),  gC12 = 4 beta^2 / (5 (1 + beta)^4),
// the coefficients are 6 pi mu a1 gA L (translation), 4 pi mu a1^2 gB(beta) L and
// 4 pi mu a2^2 gB(1/beta) L (coupling of each sphere's spin), 8 pi mu a1^3 gC L,
// pi mu (a1 + a2)^3 gC12 L and 8 pi mu a2^3 gC(1/beta) L (spin resistances, the middle one
// the cross term). Equal spheres: gA = 1/6, gB = -1/4, gC = 1/5, gC12 = 1/20; a plane
// (beta -> infinity): 8/15, -1/5, 2/5, the wall's (above; -1/5 x 4 pi = -2/15 x 6 pi). The
// asymptotic forms satisfy b1 + b2 = -(a1 + a2) a and c11 + c12 = -(a1 + a2) b1 (a rigid rotation
// of the touching pair dissipates nothing); the couplings are scaled by s = (a1 + a2) / r and the
// translation by s^2 (r the centre distance, s -> 1 at contact) so that they hold at the actual
// distance: angular momentum is then conserved exactly (diag(s, 1, 1) M diag(s, 1, 1) keeps the
// resistance matrix M positive semi-definite: the power is >= 0).
struct PairSlidingResistance {
  double translation = 0;                                 // a, N s/m
  double coupling1 = 0, coupling2 = 0;                    // b1, b2, N s (negative)
  double rotation11 = 0, rotation12 = 0, rotation22 = 0;  // c11, c12, c22, N m s
};
PairSlidingResistance pair_sliding_resistance(const LubricationLaw& law, double a1, double a2,
                                              double gap);

// Force on sphere 1 (sphere 2 gets its opposite) and the torques on both from the resistances,
// with d the unit vector from sphere 1 to sphere 2, du = v1 - v2, w1, w2 the angular velocities:
//   F1 = -a (I - d d) du - d x (b1 w1 + b2 w2),
//   T1 = -b1 (du x d) - (I - d d) (c11 w1 + c12 w2),
//   T2 = -b2 (du x d) - (I - d d) (c12 w1 + c22 w2).
// Spin about d is left out (not log-singular), like the wall's.
using Vec3 = std::array<double, 3>;
struct PairSlidingLoads {
  Vec3 force1{}, torque1{}, torque2{};
};
PairSlidingLoads pair_sliding_loads(const PairSlidingResistance& r, const Vec3& d, const Vec3& du,
                                    const Vec3& w1, const Vec3& w2);

}  // namespace lbdem
