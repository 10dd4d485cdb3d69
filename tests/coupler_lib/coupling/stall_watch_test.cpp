#include "coupler_lib/coupling/stall_watch.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace lbdem {
namespace {

PeerInfo dem_peer() {
  PeerInfo p;
  p.side = "dem";
  p.program = "dem_app";
  return p;
}

TEST(StallWatch, AFixedLimitEndsAWaitWithTheSilentSideAndTheLastStep) {
  StallWatch w(0.05, dem_peer());
  w.begin(4);
  w.end();
  w.begin(5);
  EXPECT_NO_THROW(w.check());
  std::this_thread::sleep_for(std::chrono::milliseconds(80));
  try {
    w.check();
    FAIL() << "no error after the limit";
  } catch (const SideError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("dem_app (the dem side) has sent nothing for"), std::string::npos) << m;
    EXPECT_NE(m.find("coupling.stall_timeout"), std::string::npos) << m;
    EXPECT_NE(m.find("at step 5"), std::string::npos) << m;
    EXPECT_NE(m.find("last completed exchange: step 4"), std::string::npos) << m;
    EXPECT_NE(m.find("last checkpoint: none"), std::string::npos) << m;
  }
}

TEST(StallWatch, TheAutomaticLimitIsGenerousAndGrowsWithTheSlowestExchange) {
  StallWatch w(0, dem_peer());
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kAutomaticFloor);
  w.begin(1);
  w.end();
  w.begin(2);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  w.end();
  // 50 x 20 ms is still below the floor.
  EXPECT_DOUBLE_EQ(w.limit_s(), StallWatch::kAutomaticFloor);
  w.begin(3);
  EXPECT_NO_THROW(w.check());
}

}  // namespace
}  // namespace lbdem
