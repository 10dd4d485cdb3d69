#pragma once
// Everything `fluid.output:` asks for, at the cadence it asks for: field files (HDF5 +
// one XDMF per view with all output times) and the CSV series of domain means. Constructed
// only when the scene has an output section; every method is collective over the fluid ranks.
#include <mpi.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coupler_lib/scene/fluid_output_section.hpp"
#include "fluid_app/output/field_file.hpp"
#include "fluid_app/output/field_view.hpp"
#include "fluid_app/output/series_csv.hpp"
#include "fluid_app/output/xdmf_file.hpp"

namespace lbdem {

class FluidOutput {
 public:
  FluidOutput(const FluidOutputParams& params, const UnitConverter& units,
              const std::string& scene_name, MPI_Comm comm, const std::array<int, 3>& global,
              long long series_resume_bytes = -1);

  // Whether write() has anything to do at this step (fields or series due).
  bool due(long step) const { return fields_due(step) || series_due(step); }
  void write(long step, double time, const MacroFields& fields);

  // Paths of what has been written so far (for logs and tests).
  std::vector<std::string> xdmf_files() const;
  std::optional<std::string> series_file() const;
  // Bytes of the series on disk (rank 0; -1 elsewhere or without series), for checkpoints.
  long long series_bytes() { return series_ ? series_->bytes() : -1; }

 private:
  bool fields_due(long step) const { return params_.fields && step % params_.fields->every == 0; }
  bool series_due(long step) const { return params_.series && step % params_.series->every == 0; }
  void write_fields(long step, double time, const MacroFields& fields);

  FluidOutputParams params_;
  UnitConverter units_;
  std::string prefix_;  // directory/scene_name
  MPI_Comm comm_;
  int rank_ = 0;
  std::vector<FieldView> views_;
  FieldQuantities quantities_;
  std::vector<XdmfStep> steps_;
  std::unique_ptr<SeriesCsv> series_;
};

// Creates `dir` on rank 0 and waits until it exists for everyone.
void make_output_directory(const std::string& dir, MPI_Comm comm);

}  // namespace lbdem
