#include "fluid_app/output/series_csv.hpp"

#include <iomanip>
#include <stdexcept>

#include "coupler_lib/output/series_resume.hpp"

namespace lbdem {

SeriesCsv::SeriesCsv(const std::string& path, bool writer, long long resume_bytes) : path_(path) {
  if (!writer) return;
  if (resume_bytes >= 0) {
    cut_series_to(path, resume_bytes);
    out_.open(path, std::ios::app);
    if (!out_) throw std::runtime_error("cannot append to the time series file " + path);
    out_ << std::setprecision(10);
    return;
  }
  out_.open(path, std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot create the time series file " + path);
  out_ << "step,time_s,mean_ux_m_s,mean_uy_m_s,mean_uz_m_s,kinetic_energy_J,"
          "mean_density_kg_m3,max_mach\n";
  out_ << std::setprecision(10);
  out_.flush();
}

long long SeriesCsv::bytes() {
  if (!out_.is_open()) return -1;
  out_.flush();
  return static_cast<long long>(out_.tellp());
}

void SeriesCsv::append(long step, double time, const DomainMeans& m) {
  if (!out_.is_open()) return;
  out_ << step << ',' << time << ',' << m.mean_velocity[0] << ',' << m.mean_velocity[1] << ','
       << m.mean_velocity[2] << ',' << m.kinetic_energy << ',' << m.mean_density << ','
       << m.max_mach << '\n';
  // Flushed per row so the series can be watched (and survives a crash) while running.
  out_.flush();
}

}  // namespace lbdem
