#pragma once
// Plane channel flows between two walls at y = 0 and y = H, started from rest at t = 0
// (solutions of the unsteady Stokes equation u_t = nu u_yy + g, u(0) = U0, u(H) = U1, by
// separation of variables; the series converge like n^-3 (Poiseuille) and n^-1 e^{-n^2 ...}
// (Couette), and are summed until the terms no longer change the result).
namespace lbdem {

// Body-force driven (acceleration g along the walls, both walls at rest):
//   u(y, t) = g y (H - y) / (2 nu)
//             - sum_{n odd} 4 g H^2 / (nu n^3 pi^3) sin(n pi y / H) exp(-n^2 pi^2 nu t / H^2).
double poiseuille_velocity(double y, double height, double accel, double nu, double t);

// Wall driven (wall at y = 0 moving with u0, at y = H with u1, no force):
//   u(y, t) = u0 + (u1 - u0) y / H
//             + sum_{n >= 1} 2 (u1 (-1)^n - u0) / (n pi) sin(n pi y / H) exp(-n^2 pi^2 nu t / H^2).
// At t = 0 the series is slowly convergent; it is meant for t > 0.
double couette_velocity(double y, double height, double u0, double u1, double nu, double t);

}  // namespace lbdem
