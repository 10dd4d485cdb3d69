#include <gtest/gtest.h>

#include "dem_app/contact/restitution_map.hpp"

namespace lbdem {
namespace {

// LAMMPS measured e = 0.928 for p = 0.9 and e = 0.900 for p = 0.8621 (shared notes); the
// scaled Hertz-Tsuji collision must reproduce both.
TEST(RestitutionMap, ReproducesLammpsMeasurements) {
  EXPECT_NEAR(restitution_for_alpha(tsuji_alpha(0.9)), 0.928, 1e-3);
  EXPECT_NEAR(restitution_for_alpha(tsuji_alpha(0.8621)), 0.900, 1e-3);
}

TEST(RestitutionMap, InvertsForRequestedRestitution) {
  for (double e : {0.2, 0.5, 0.7, 0.9, 0.95}) {
    const double p = tsuji_parameter_for(e);
    EXPECT_GE(p, 0.0);
    EXPECT_LE(p, 1.0);
    EXPECT_NEAR(restitution_for_alpha(tsuji_alpha(p)), e, 1e-9) << "e = " << e;
  }
}

TEST(RestitutionMap, RejectsUnreachableRestitution) {
  EXPECT_THROW(tsuji_parameter_for(0.05), std::invalid_argument);
  EXPECT_THROW(tsuji_parameter_for(0.9999), std::invalid_argument);
}

TEST(RestitutionMap, UndampedCollisionIsElastic) {
  EXPECT_NEAR(restitution_for_alpha(0.0), 1.0, 1e-9);
}

}  // namespace
}  // namespace lbdem
