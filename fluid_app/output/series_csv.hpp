#pragma once
// The compact time series of domain means as CSV, one row per output time, written by rank 0
// of the fluid side only (the values are already reduced). Columns:
//   step, time_s, mean_ux_m_s, mean_uy_m_s, mean_uz_m_s, kinetic_energy_J,
//   mean_density_kg_m3, max_mach
#include <fstream>
#include <string>

#include "fluid_app/output/domain_means.hpp"

namespace lbdem {

class SeriesCsv {
 public:
  // Every rank constructs it; only `writer` opens (and truncates) the file.
  // `resume_bytes` >= 0: continue a restarted run's series, cut back to that length.
  SeriesCsv(const std::string& path, bool writer, long long resume_bytes = -1);
  // Bytes on disk so far (the writer; -1 elsewhere): what a checkpoint stores.
  long long bytes();
  void append(long step, double time, const DomainMeans& m);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace lbdem
