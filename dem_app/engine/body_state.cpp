#include "dem_app/engine/body_state.hpp"

#include <cmath>

namespace lbdem {

BodyRecord record_from_row(const double* r) {
  BodyRecord b;
  b.id = std::llround(r[0]) - 1;  // molecule IDs are 1-based
  b.x = {r[1], r[2], r[3]};
  b.x_unwrapped = {r[4], r[5], r[6]};
  b.v = {r[7], r[8], r[9]};
  b.omega = {r[10], r[11], r[12]};
  b.angmom = {r[13], r[14], r[15]};
  b.force = {r[16], r[17], r[18]};
  b.torque = {r[19], r[20], r[21]};
  b.q_lammps = Eigen::Quaterniond(r[22], r[23], r[24], r[25]);
  return b;
}

}  // namespace lbdem
