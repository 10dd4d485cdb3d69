#pragma once
// Galilean-invariant momentum exchange (Wen et al. 2014; docs/method.md Eqs. (9)-(10)), per
// solid node, in lattice units.
//
// For a node x of body k (d(x) < 1, body(x) = k) and each direction i whose neighbour
// x + c_i does not belong to body k, with f the post-stream populations:
//   f_i(x + c_i)  crossed the link out of the body (velocity  c_i),
//   f_ĩ(x)        crossed the link into the body   (velocity -c_i),
// and the body gains
//   F(x) = -sum_i [ (c_i - u_p) f_i(x + c_i) + (c_i + u_p) f_ĩ(x) ],
//   T(x) = min_image(x - x_k) x F(x),
// with u_p = v_k + w_k x min_image(x - x_k) the solid velocity at x (paper, Eq.
// solidVelocity). A population entering the body deposits its momentum -c_i f_ĩ(x), one
// leaving takes c_i f_i(x + c_i) away; the -u_p/+u_p terms make the force vanish for a body
// moving with a uniform equilibrium flow (Galilean invariance).
//
// Link set: the paper takes the links to pure fluid nodes (d = 1). For an isolated body the
// two are the same. Where the porous bands of two bodies overlap (bodies closer than about
// two cells, i.e. in or near contact) the paper's set drops the links into the other body's
// band, and then even a fluid at rest exerts a net force on each body (the ambient
// pressure times the dropped surface). Taking every link whose far end is not body k's
// keeps the link set closed, so a uniform state exerts no force whatever the neighbours,
// and the momentum crossing a link between two bodies is counted once on each, with
// opposite signs.
#include <array>
#include <cstdint>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "fluid_app/hlbm/body_field.hpp"

#include "fluid_app/hlbm/subdomain.hpp"
#include "fluid_app/lattice/d3q19.hpp"
#include "fluid_app/porous_field.hpp"

namespace lbdem::hlbm {

struct LinkLoad {
  std::array<double, 3> force{0, 0, 0};
  std::array<double, 3> torque{0, 0, 0};
  LinkLoad& operator+=(const LinkLoad& o) {
    for (int a = 0; a < 3; ++a) {
      force[a] += o.force[a];
      torque[a] += o.torque[a];
    }
    return *this;
  }
};

// Minimum-image offset of local cell (x, y, z) from the centre of body b, lattice units.
template <class T>
std::array<double, 3> lever_arm(const Subdomain& sub, const PorousBody<T>& b,
                                const std::array<int, 3>& l) {
  std::array<double, 3> r;
  for (int a = 0; a < 3; ++a) r[a] = sub.min_image(a, sub.position(a, l[a]) - double(b.centre[a]));
  return r;
}

// Force and torque on body k from the boundary links of interior cell `cell`.
// f(i, cell) returns the post-stream population i (fluid_app/lattice/d3q19.hpp order).
template <class T, class Populations>
LinkLoad link_load(const Subdomain& sub, const PorousField<T>& field, std::int32_t k,
                   CellIndex cell, const Populations& f) {
  const auto l = sub.box.coords(cell);
  const PorousBody<T> b = field.bodies[static_cast<std::size_t>(k)];
  const std::array<double, 3> r = lever_arm(sub, b, l);
  const std::array<double, 3> u = solid_velocity(b, r);
  LinkLoad out;
  for (int i = 1; i < d3q19::Q; ++i) {
    const auto& c = d3q19::c[static_cast<std::size_t>(i)];
    const CellIndex nb = cell + sub.box.shift(c[0], c[1], c[2]);
    if (field.body[static_cast<std::size_t>(nb)] == k) continue;
    const double leaving = double(f(i, nb));
    const double entering = double(f(d3q19::opposite(i), cell));
    for (int a = 0; a < 3; ++a) out.force[a] -= (c[a] - u[a]) * leaving + (c[a] + u[a]) * entering;
  }
  out.torque = {r[1] * out.force[2] - r[2] * out.force[1],
                r[2] * out.force[0] - r[0] * out.force[2],
                r[0] * out.force[1] - r[1] * out.force[0]};
  return out;
}

// The loads on every body of a BodyField's last update by momentum exchange over the boundary
// links of the cells this rank owns (fluid.loads: momentum_exchange; it misses the momentum of
// cells that enter or leave a moving body's band and the body force inside it), SI, torque
// about the centre of mass, in slot order. f(i, cell): post-stream population i at local cell
// `cell` (FluidSolver::population).
template <class T, class Populations>
std::vector<BodyLoad> momentum_exchange(const BodyField<T>& bodies, const Populations& f,
                                        std::int64_t step) {
  const Subdomain& sub = bodies.subdomain();
  const PorousField<T>& field = bodies.field();
  const UnitConverter& units = bodies.frame().units;
  std::vector<BodyLoad> loads;
  for (std::size_t s = 0; s < bodies.slots(); ++s) {
    const auto slot = static_cast<std::int32_t>(s);
    if (bodies.id_of(slot) < 0) continue;
    // Interior cells (d = 0) never neighbour a cell outside the body (the smoothing is
    // wider than a link, docs/method.md "Momentum exchange"), so the body's band holds all its
    // boundary links.
    LinkLoad sum;
    for (const auto& b : bodies.band(slot)) {
      const CellIndex c = b.cell(sub.box);
      if (field.body[c] == slot && sub.box.interior(b.l[0], b.l[1], b.l[2]))
        sum += link_load(sub, field, slot, c, f);
    }
    BodyLoad load;
    load.id = bodies.id_of(slot);
    load.step = step;
    for (int a = 0; a < 3; ++a) {
      load.f[a] = sum.force[a] * units.force();
      load.t[a] = sum.torque[a] * units.torque();
    }
    loads.push_back(load);
  }
  return loads;
}

}  // namespace lbdem::hlbm
