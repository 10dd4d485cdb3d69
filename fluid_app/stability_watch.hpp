#pragma once
// The stability watch: every `interval` steps it scans the macroscopic state for non-finite
// values, non-positive density and Mach above the scene's limit. All fluid ranks agree on the
// outcome through reductions on the side communicator, so either every rank goes on or every
// rank stops with the same diagnosis. A passing check keeps the state it checked (density and
// velocity, 4 numbers per node; taken over by swapping buffers, not copied) so that a failing
// one can write the last good state to HDF5.
#include <mpi.h>

#include <optional>
#include <string>

#include "coupler_lib/scene/fluid_output_section.hpp"
#include "fluid_app/output/macro_fields.hpp"
#include "fluid_app/stability_diagnosis.hpp"

namespace lbdem {

struct StabilityFailure {
  InstabilityReport report;
  std::string last_good_file;  // empty when no check had passed before
  std::string message;         // describe_instability(...), identical on every rank
};

class StabilityWatch {
 public:
  StabilityWatch(const StabilityParams& params, const UnitConverter& units, MPI_Comm comm,
                 std::string last_good_file);

  bool due(long step) const { return params_.interval > 0 && step % params_.interval == 0; }

  // Collective. nullopt: the state is fine and becomes last_good(); `fields` is swapped with
  // the previous last good state (its contents are then stale, to be refilled by the caller).
  // Otherwise the same failure on every rank, after the last good state was written
  // collectively; `fields` is left as it was.
  std::optional<StabilityFailure> check(long step, double time, MacroFields& fields);
  const MacroFields& last_good() const { return last_good_; }

 private:
  StabilityParams params_;
  UnitConverter units_;
  MPI_Comm comm_;
  std::string last_good_file_;
  MacroFields last_good_;
  long last_good_step_ = -1;
  double last_good_time_ = 0;
  double last_good_mach_ = 0;
};

// The local part of a check (no communication): the worst kind on this block and the node
// that represents it (largest Mach, or first node in global x-fastest order for the others).
struct LocalScan {
  Instability kind = Instability::none;
  std::array<int, 3> cell{};
  double rho = 0;
  std::array<double, 3> u{};
  double mach = 0;          // at `cell`
  double max_mach = 0;      // over the finite nodes of the block
  long long bad_cells = 0;  // nodes of kind `kind`
};
LocalScan scan_block(const MacroFields& f, double max_mach);

}  // namespace lbdem
