// The home table of the DEM loads: who is home, the last load set wins, and the run's
// first-evaluation correction (F_new - F_old) / 2 with F_old the load of the previous run,
// whether or not the body was asked for in between.
#include <gtest/gtest.h>

#include <stdexcept>

#include "dem_app/load_table.hpp"

namespace lbdem {
namespace {

LoadUpdate load(std::int64_t id, double f, double t) {
  return {id, 0, {f, 2 * f, 3 * f}, {t, 0, -t}};
}

TEST(LoadTable, HomesAreIdModRanks) {
  const LoadTable t(10, 1, 3);  // rank 1 of 3: bodies 1, 4, 7
  EXPECT_EQ(t.size(), 3u);
  EXPECT_TRUE(t.is_home(4));
  EXPECT_FALSE(t.is_home(5));
  EXPECT_EQ(t.home(5), 2);
  EXPECT_THROW(t.applied(5, false), std::out_of_range);
  EXPECT_THROW(t.applied(10, false), std::out_of_range);
  EXPECT_EQ(LoadTable(2, 2, 3).size(), 0u);
}

TEST(LoadTable, KickIsHalfTheChangeSinceThePreviousRun) {
  LoadTable t(1, 0, 1);
  t.update({0, 1, {0, 0, -5}, {0, 0, 0}});  // extra force
  t.update(load(0, 9, 9));                  // replaced before the run: the last one wins
  t.update(load(0, 2, 1));
  t.begin_run();  // run 1
  AppliedLoad a = t.applied(0, true);
  EXPECT_EQ(a.force[0], 2.0);
  EXPECT_EQ(a.force[2], 6.0 - 5.0);
  EXPECT_EQ(a.torque[2], -1.0);
  EXPECT_EQ(a.kick_force[1], 0.5 * 4.0);  // from zero
  EXPECT_EQ(a.kick_torque[0], 0.5);
  EXPECT_EQ(t.applied(0, false).kick_force[1], 0.0);  // a single-substep run has none

  t.begin_run();  // run 2, load unchanged: no correction
  a = t.applied(0, true);
  EXPECT_EQ(a.force[0], 2.0);
  EXPECT_EQ(a.kick_force[0], 0.0);

  t.update(load(0, 3, 0));  // set twice for run 3: the old load is still run 2's
  t.update(load(0, 5, 0));
  t.begin_run();
  a = t.applied(0, true);
  EXPECT_EQ(a.force[0], 5.0);
  EXPECT_EQ(a.kick_force[0], 0.5 * (5.0 - 2.0));
  EXPECT_EQ(a.kick_torque[0], 0.5 * (0.0 - 1.0));

  t.begin_run();  // run 4 not asked for; run 5 sets a new load: old is run 3's (and 4's)
  t.update(load(0, 7, 0));
  t.begin_run();
  EXPECT_EQ(t.applied(0, true).kick_force[0], 0.5 * (7.0 - 5.0));
}

}  // namespace
}  // namespace lbdem
