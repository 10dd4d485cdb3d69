#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <vector>

#include "fluid_app/output/field_file.hpp"
#include "fluid_app/stability/stability_watch.hpp"
#include "output/output_test_support.hpp"

namespace lbdem {
namespace {

const UnitConverter kUnits = UnitConverter::from_tau(0.001, 0.6, 1e-6, 1000.0);

MacroFields calm(const FieldBlock& box) {
  MacroFields f;
  f.resize(box);
  std::fill(f.rho.begin(), f.rho.end(), 1.0);
  std::fill(f.u.begin(), f.u.end(), 0.01);
  return f;
}

TEST(StabilityScan, WorstKindWinsAndFirstNodeIsInGlobalOrder) {
  FieldBlock box{{8, 8, 8}, {2, 0, 4}, {4, 3, 2}};
  MacroFields f = calm(box);
  f.u[3 * box.index(3, 2, 1)] = 0.5;  // Mach 0.87
  f.rho[box.index(1, 1, 1)] = -0.1;
  f.rho[box.index(2, 2, 0)] = -0.2;  // earlier in global order (lower z)
  LocalScan s = scan_block(f, 0.3);
  EXPECT_EQ(s.kind, Instability::density);
  EXPECT_EQ(s.bad_cells, 2);
  EXPECT_EQ(s.cell, (std::array<int, 3>{4, 2, 4}));
  EXPECT_DOUBLE_EQ(s.rho, -0.2);

  f.u[3 * box.index(0, 2, 1) + 2] = std::numeric_limits<double>::quiet_NaN();
  s = scan_block(f, 0.3);
  EXPECT_EQ(s.kind, Instability::not_finite);
  EXPECT_EQ(s.cell, (std::array<int, 3>{2, 2, 5}));
}

TEST(StabilityScan, MachReportsTheFastestNode) {
  FieldBlock box{{4, 4, 4}, {0, 0, 0}, {4, 4, 4}};
  MacroFields f = calm(box);
  f.u[3 * box.index(1, 0, 0)] = 0.2;
  f.u[3 * box.index(3, 3, 3) + 1] = -0.25;
  const LocalScan s = scan_block(f, 0.3);
  EXPECT_EQ(s.kind, Instability::mach);
  EXPECT_EQ(s.bad_cells, 2);
  EXPECT_EQ(s.cell, (std::array<int, 3>{3, 3, 3}));
  EXPECT_NEAR(s.mach, std::sqrt(3.0 * (0.25 * 0.25 + 2e-4)), 1e-12);
}

TEST(StabilityDiagnosis, MachMessageSaysWhereWhenAndWhatToChange) {
  InstabilityReport r;
  r.kind = Instability::mach;
  r.cell = {3, 4, 5};
  r.mach = 0.45;
  r.max_mach = 0.3;
  r.step = 1200;
  r.time = 0.5;
  r.last_good_step = 1100;
  const std::string m = describe_instability(r, kUnits, "out/x_last_good.h5");
  EXPECT_NE(m.find("Mach 0.45 > 0.3"), std::string::npos) << m;
  EXPECT_NE(m.find("cell (3, 4, 5) at x = (0.0035, 0.0045, 0.0055) m"), std::string::npos) << m;
  EXPECT_NE(m.find("step 1200, t = 0.5 s"), std::string::npos) << m;
  // Mach scales with dx and with tau - 1/2: 0.001 * 0.3/0.45 and 0.5 + 0.1 * 0.3/0.45.
  EXPECT_NE(m.find("fluid.dx to <= 0.0006667 m"), std::string::npos) << m;
  EXPECT_NE(m.find("fluid.tau to <= 0.5667"), std::string::npos) << m;
  EXPECT_NE(m.find("written to out/x_last_good.h5"), std::string::npos) << m;
}

TEST(StabilityWatch, EveryPassingCheckWritesTheLastGoodStateAFailingOneKeepsIt) {
  test::ScratchDir dir("lbdem_stability");
  const std::string lg = dir.file("lg.h5");
  StabilityParams p;
  p.interval = 10;
  StabilityWatch w(p, kUnits, MPI_COMM_SELF, lg);
  EXPECT_TRUE(w.due(20));
  EXPECT_FALSE(w.due(25));
  FieldBlock box{{3, 2, 2}, {0, 0, 0}, {3, 2, 2}};
  MacroFields f = calm(box);
  EXPECT_FALSE(w.check(10, 0.1, f));
  ASSERT_TRUE(std::filesystem::exists(lg));
  EXPECT_DOUBLE_EQ(test::read_double_attribute(lg, "/", "time"), 0.1);
  f.rho[box.index(2, 1, 0)] = 1.25;  // still fine: becomes the last good state
  const MacroFields checked = f;
  EXPECT_FALSE(w.check(20, 0.2, f));
  EXPECT_EQ(f.rho, checked.rho);  // the checked fields are left as they were
  EXPECT_DOUBLE_EQ(test::read_double_attribute(lg, "/", "time"), 0.2);
  EXPECT_TRUE(std::filesystem::exists(dir.file("lg.xdmf")));
  EXPECT_FALSE(std::filesystem::exists(lg + ".tmp"));

  MacroFields bad = f;
  bad.rho[box.index(1, 1, 1)] = std::numeric_limits<double>::infinity();
  const auto failure = w.check(30, 0.3, bad);
  ASSERT_TRUE(failure);
  EXPECT_EQ(failure->report.kind, Instability::not_finite);
  EXPECT_EQ(failure->report.cell, (std::array<int, 3>{1, 1, 1}));
  EXPECT_EQ(failure->last_good_file, lg);
  EXPECT_NE(failure->message.find("not finite"), std::string::npos) << failure->message;
  EXPECT_NE(failure->message.find("step 20"), std::string::npos) << failure->message;
  // The failing state replaced nothing: the file is step 20's, the candidate is gone.
  EXPECT_FALSE(std::filesystem::exists(lg + ".tmp"));
  EXPECT_DOUBLE_EQ(test::read_double_attribute(lg, "/", "time"), 0.2);
  const auto rho = test::read_dataset(lg, "/volume/density");
  ASSERT_EQ(rho.values.size(), 12u);
  EXPECT_DOUBLE_EQ(rho.values[box.index(2, 1, 0)], 1250.0);
  EXPECT_DOUBLE_EQ(rho.values[box.index(1, 1, 1)], 1000.0);
}

TEST(StabilityWatch, ARunItDidNotStopRemovesTheLastGoodFile) {
  test::ScratchDir dir("lbdem_stability_done");
  const std::string lg = dir.file("lg.h5");
  StabilityWatch w(StabilityParams{}, kUnits, MPI_COMM_SELF, lg);
  FieldBlock box{{2, 2, 2}, {0, 0, 0}, {2, 2, 2}};
  EXPECT_FALSE(w.check(100, 1.0, calm(box)));
  ASSERT_TRUE(std::filesystem::exists(lg));
  w.remove_last_good();
  EXPECT_FALSE(std::filesystem::exists(lg));
  EXPECT_FALSE(std::filesystem::exists(dir.file("lg.xdmf")));
}

TEST(StabilityWatch, AFailureBeforeAnyPassingCheckNamesNoFile) {
  test::ScratchDir dir("lbdem_stability_first");
  const std::string lg = dir.file("lg.h5");
  StabilityParams p;
  StabilityWatch w(p, kUnits, MPI_COMM_SELF, lg);
  FieldBlock box{{2, 2, 2}, {0, 0, 0}, {2, 2, 2}};
  MacroFields f = calm(box);
  f.rho[0] = -1.0;
  const auto failure = w.check(100, 1.0, f);
  ASSERT_TRUE(failure);
  EXPECT_EQ(failure->report.kind, Instability::density);
  EXPECT_TRUE(failure->last_good_file.empty());
  EXPECT_FALSE(std::filesystem::exists(lg));
  EXPECT_FALSE(std::filesystem::exists(lg + ".tmp"));
}

// The state given a slab at a time is written as the whole block: every node once, in place.
TEST(StabilityWatch, SlabsWriteTheWholeBlock) {
  test::ScratchDir dir("lbdem_stability_slabs");
  const std::string lg = dir.file("lg.h5");
  StabilityParams p;
  StabilityWatch w(p, kUnits, MPI_COMM_SELF, lg);
  FieldBlock box{{3, 2, 5}, {0, 0, 0}, {3, 2, 5}};
  MacroFields f = calm(box);
  for (std::size_t c = 0; c < box.cells(); ++c) {
    f.rho[c] = 1.0 + 1e-3 * double(c);
    f.u[3 * c + 2] = -1e-4 * double(c);
  }
  MacroFields slab;
  int calls = 0;
  EXPECT_FALSE(w.check(100, 1.0, box, 2, [&](int z0, int z1) -> const MacroFields& {
    ++calls;
    slab.resize(FieldBlock{box.global, {0, 0, z0}, {box.n[0], box.n[1], z1 - z0}});
    for (int k = z0; k < z1; ++k)
      for (int j = 0; j < box.n[1]; ++j)
        for (int i = 0; i < box.n[0]; ++i) {
          const std::size_t c = box.index(i, j, k), s = slab.box.index(i, j, k - z0);
          slab.rho[s] = f.rho[c];
          for (int a = 0; a < 3; ++a) slab.u[3 * s + a] = f.u[3 * c + a];
        }
    return slab;
  }));
  EXPECT_EQ(calls, 3);  // planes 0-1, 2-3, 4
  const auto rho = test::read_dataset(lg, "/volume/density");
  const auto u = test::read_dataset(lg, "/volume/velocity");
  ASSERT_EQ(rho.values.size(), box.cells());
  ASSERT_EQ(u.values.size(), 3 * box.cells());
  for (std::size_t c = 0; c < box.cells(); ++c) {
    EXPECT_EQ(rho.values[c], double(float(si_density(f.rho[c], kUnits)))) << c;
    EXPECT_EQ(u.values[3 * c + 2], double(float(si_velocity(f.u[3 * c + 2], kUnits)))) << c;
  }
}

TEST(StabilityScan, SlabsMergeToTheScanOfTheWholeBlock) {
  FieldBlock box{{8, 8, 8}, {2, 0, 1}, {4, 3, 6}};
  MacroFields f = calm(box);
  f.u[3 * box.index(3, 2, 1)] = 0.5;   // Mach 0.87
  f.u[3 * box.index(1, 0, 4)] = -0.6;  // Mach 1.04, the fastest, in a later slab
  f.rho[box.index(1, 1, 5)] = -0.1;    // density: worse than Mach, later in global order
  f.rho[box.index(2, 2, 2)] = -0.2;
  for (int planes : {1, 2, 4}) {
    LocalScan merged;
    for (int z0 = 0; z0 < box.n[2]; z0 += planes) {
      MacroFields slab;
      const int nz = std::min(planes, box.n[2] - z0);
      slab.resize(
          FieldBlock{box.global, {box.lo[0], box.lo[1], box.lo[2] + z0}, {box.n[0], box.n[1], nz}});
      for (int k = 0; k < nz; ++k)
        for (int j = 0; j < box.n[1]; ++j)
          for (int i = 0; i < box.n[0]; ++i) {
            const std::size_t c = box.index(i, j, z0 + k), s = slab.box.index(i, j, k);
            slab.rho[s] = f.rho[c];
            for (int a = 0; a < 3; ++a) slab.u[3 * s + a] = f.u[3 * c + a];
          }
      merge_scan(merged, scan_block(slab, 0.3), box.global);
    }
    const LocalScan whole = scan_block(f, 0.3);
    EXPECT_EQ(merged.kind, whole.kind) << planes;
    EXPECT_EQ(merged.cell, whole.cell) << planes;
    EXPECT_EQ(merged.bad_cells, whole.bad_cells) << planes;
    EXPECT_EQ(merged.rho, whole.rho) << planes;
    EXPECT_EQ(merged.max_mach, whole.max_mach) << planes;
    f.rho[box.index(1, 1, 5)] = -0.1;
  }
  // Mach alone: the fastest node, wherever its slab.
  f.rho[box.index(1, 1, 5)] = 1.0;
  f.rho[box.index(2, 2, 2)] = 1.0;
  LocalScan merged;
  for (int z0 = 0; z0 < box.n[2]; ++z0) {
    MacroFields slab;
    slab.resize(
        FieldBlock{box.global, {box.lo[0], box.lo[1], box.lo[2] + z0}, {box.n[0], box.n[1], 1}});
    for (int j = 0; j < box.n[1]; ++j)
      for (int i = 0; i < box.n[0]; ++i) {
        const std::size_t c = box.index(i, j, z0), s = slab.box.index(i, j, 0);
        slab.rho[s] = f.rho[c];
        for (int a = 0; a < 3; ++a) slab.u[3 * s + a] = f.u[3 * c + a];
      }
    merge_scan(merged, scan_block(slab, 0.3), box.global);
  }
  const LocalScan whole = scan_block(f, 0.3);
  EXPECT_EQ(merged.kind, Instability::mach);
  EXPECT_EQ(merged.cell, whole.cell);
  EXPECT_EQ(merged.mach, whole.mach);
  EXPECT_EQ(merged.bad_cells, 2);
}

TEST(StabilityWatch, IntervalZeroSwitchesItOff) {
  StabilityParams p;
  p.interval = 0;
  StabilityWatch w(p, kUnits, MPI_COMM_SELF, "unused.h5");
  EXPECT_FALSE(w.due(0));
  EXPECT_FALSE(w.due(100));
}

}  // namespace
}  // namespace lbdem
