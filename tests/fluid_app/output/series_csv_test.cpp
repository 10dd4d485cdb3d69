#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "fluid_app/output/domain_means.hpp"
#include "fluid_app/output/series_csv.hpp"
#include "output_test_support.hpp"

namespace lbdem {
namespace {

TEST(DomainMeans, SiMeansEnergyAndMachOfAKnownState) {
  const UnitConverter units = UnitConverter::from_tau(0.01, 0.8, 1e-3, 1000.0);
  FieldBlock box{{2, 1, 1}, {0, 0, 0}, {2, 1, 1}};
  MacroFields f;
  f.resize(box);
  f.rho = {1.0, 1.2};
  f.u = {0.03, 0.0, 0.0, 0.0, -0.04, 0.0};
  const DomainMeans m = domain_means(f, units, MPI_COMM_SELF);
  const double v = units.velocity();
  EXPECT_DOUBLE_EQ(m.mean_velocity[0], 0.015 * v);
  EXPECT_DOUBLE_EQ(m.mean_velocity[1], -0.02 * v);
  EXPECT_DOUBLE_EQ(m.mean_density, 1100.0);
  const double ke = 0.5 * 1000.0 * (1.0 * 0.03 * 0.03 + 1.2 * 0.04 * 0.04) * v * v * 1e-6;
  EXPECT_NEAR(m.kinetic_energy, ke, 1e-12 * ke);
  EXPECT_DOUBLE_EQ(m.max_mach, 0.04 * std::sqrt(3.0));
}

TEST(SeriesCsv, HeaderAndOneRowPerAppend) {
  test::ScratchDir dir("lbdem_series");
  const std::string path = dir.file("s.csv");
  {
    SeriesCsv csv(path, true);
    DomainMeans m;
    m.mean_velocity = {1, 2, 3};
    m.kinetic_energy = 4;
    m.mean_density = 1000;
    m.max_mach = 0.05;
    csv.append(10, 0.5, m);
    csv.append(20, 1.0, m);
  }
  std::ifstream in(path);
  std::string header, row1, row2, extra;
  std::getline(in, header);
  std::getline(in, row1);
  std::getline(in, row2);
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(header,
            "step,time_s,mean_ux_m_s,mean_uy_m_s,mean_uz_m_s,kinetic_energy_J,"
            "mean_density_kg_m3,max_mach");
  EXPECT_EQ(row1, "10,0.5,1,2,3,4,1000,0.05");
  EXPECT_EQ(row2.substr(0, 5), "20,1,");
}

TEST(SeriesCsv, NonWritingRanksCreateNothing) {
  test::ScratchDir dir("lbdem_series_quiet");
  SeriesCsv csv(dir.file("s.csv"), false);
  csv.append(0, 0.0, DomainMeans{});
  EXPECT_FALSE(std::filesystem::exists(dir.file("s.csv")));
}

}  // namespace
}  // namespace lbdem
