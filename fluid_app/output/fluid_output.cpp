#include "fluid_app/output/fluid_output.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "fluid_app/output/domain_means.hpp"

namespace lbdem {

void make_output_directory(const std::string& dir, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int ok = 1;
  std::string error;
  if (rank == 0) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
      ok = 0;
      error = ec.message();
    }
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, comm);
  if (!ok) throw std::runtime_error("cannot create the output directory '" + dir + "': " + error);
}

FluidOutput::FluidOutput(const FluidOutputParams& params, const UnitConverter& units,
                         const std::string& scene_name, MPI_Comm comm,
                         const std::array<int, 3>& global, long long series_resume_bytes)
    : params_(params), units_(units), comm_(comm) {
  MPI_Comm_rank(comm, &rank_);
  make_output_directory(params.directory, comm);
  prefix_ = (std::filesystem::path(params.directory) / scene_name).string();
  if (params.fields) {
    views_ = views_for(*params.fields, global);
    quantities_ = {params.fields->velocity, params.fields->density, params.fields->pressure,
                   params.fields->double_precision};
  }
  if (params.series)
    series_ = std::make_unique<SeriesCsv>(prefix_ + "_series.csv", rank_ == 0, series_resume_bytes);
}

void FluidOutput::write(long step, double time, const MacroFields& fields) {
  if (fields_due(step)) write_fields(step, time, fields);
  if (series_due(step)) series_->append(step, time, domain_means(fields, units_, comm_));
}

void FluidOutput::write_fields(long step, double time, const MacroFields& fields) {
  char index[16];
  std::snprintf(index, sizeof index, "%06zu", steps_.size());
  const std::string h5 = prefix_ + "_fields_" + index + ".h5";
  write_field_file(h5, comm_, views_, quantities_, fields, units_, step, time);
  steps_.push_back({time, std::filesystem::path(h5).filename().string()});
  if (rank_ == 0) {
    // Rewritten at every output so it is complete whenever the run stops.
    for (const auto& v : views_)
      write_file_atomically(prefix_ + "_" + v.name + ".xdmf",
                            xdmf_text(v, quantities_, units_.dx, steps_));
  }
}

std::vector<std::string> FluidOutput::xdmf_files() const {
  std::vector<std::string> out;
  for (const auto& v : views_) out.push_back(prefix_ + "_" + v.name + ".xdmf");
  return out;
}

std::optional<std::string> FluidOutput::series_file() const {
  if (!series_) return std::nullopt;
  return series_->path();
}

}  // namespace lbdem
