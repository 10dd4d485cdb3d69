#pragma once
// Lattice links that leave the domain through a non-periodic face, and the rule that gives
// the population coming back along each of them (applied after every step, after the halo
// exchange). For a link from interior cell x along c_i, f*_i(x) is the post-collision value
// that would leave; the rule sets f_ibar(x) for the next step (ibar = opposite(i)):
//   wall        half-way bounce-back: f_ibar = f*_i  (the wall lies half a cell beyond x);
//   moving_wall bounce-back with the momentum of the wall velocity u_w
//               (Krueger et al. 2017, Eq. 5.27): f_ibar = f*_i - 6 w_i rho(x) c_i.u_w;
//   pressure    anti-bounce-back at the prescribed density rho_w = 1 + 3 p
//               (Krueger et al. 2017, Eq. 5.53):
//               f_ibar = -f*_i + 2 w_i rho_w (1 + 9/2 (c_i.u)^2 - 3/2 u^2),
//               with u the post-collision velocity of x (zeroth-order extrapolation to the
//               wall). It fixes the pressure, lets any velocity through and, unlike
//               equilibrium-type open boundaries, keeps the non-equilibrium part, which is
//               what makes it stable for the side walls of settling boxes.
// A link that crosses two boundary faces at once (box edge) takes a wall rule before a
// pressure rule, then the lower face index.
#include <array>
#include <cstdint>
#include <vector>

#include "fluid_app/parallel/decomposition.hpp"

namespace lbdem {

enum class FaceType;

// A face's rule in lattice units.
struct FaceRule {
  int type = 0;                      // static_cast<int>(FaceType)
  std::array<double, 3> velocity{};  // moving wall
  double density = 1;                // pressure: rho_w
};

template <class T>
class BoundaryLinks {
 public:
  BoundaryLinks(const Decomposition& dec, const std::array<FaceRule, 6>& faces, CellIndex stride);
  // `after_odd`: AA parity of the step just done.
  void apply(T* f, bool after_odd) const;
  std::size_t size() const { return link_i_.size(); }

 private:
  struct Cell {
    CellIndex cell;
    std::uint32_t first, count;
    bool moments;  // a rule needs rho/u of the cell
  };
  std::array<FaceRule, 6> faces_;
  CellIndex stride_;
  std::array<CellIndex, 19> shift_{};
  std::vector<Cell> cells_;
  std::vector<std::int8_t> link_i_, link_face_;
};

extern template class BoundaryLinks<double>;
extern template class BoundaryLinks<float>;

}  // namespace lbdem
