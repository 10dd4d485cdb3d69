#pragma once
// A rank's block of the global lattice as the HLBM operators see it: the fluid core's
// LocalBox (interior cells 1..n, one ghost layer 0 and n+1) plus which axes are periodic.
//
// Lattice coordinates (the fluid core's convention, fluid_app/porous_field.hpp): global node
// g sits at g + 1/2, so a lattice position is the SI position minus the domain's lower
// corner, divided by dx.
#include <array>

#include "coupler_lib/geometry/periodic.hpp"
#include "fluid_app/lattice/local_box.hpp"

namespace lbdem::hlbm {

struct Subdomain {
  LocalBox box;
  std::array<bool, 3> periodic{true, true, true};

  // Lattice position of local coordinate l (0..n+1) along axis a.
  double position(int a, int l) const { return box.offset[a] + (l - 1) + 0.5; }
  bool stored(int a, int l) const { return l >= 0 && l <= box.n[a] + 1; }

  // Minimum-image convention (paper, appendix "How forces on particles are calculated"):
  // in a periodic direction an offset is shifted by the domain length to its nearest image.
  double min_image(int a, double r) const {
    if (!periodic[a]) return r;
    return lbdem::min_image(r, double(box.global[a]));
  }
};

}  // namespace lbdem::hlbm
