#pragma once
// The stability watch: every `interval` steps it scans the macroscopic state for non-finite
// values, non-positive density and Mach above the scene's limit. All fluid ranks agree on the
// outcome through reductions on the side communicator, so either every rank goes on or every
// rank stops with the same diagnosis. A passing check keeps the state it checked (density and
// velocity, 4 numbers per node, in float: 16 B per node) so that a failing one can write the
// last good state to HDF5. The checked state need not exist as a whole: the caller may scan it
// in slabs and store it when asked (RunWatch does, docs/performance.md "Memory per cell").
#include <mpi.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "coupler_lib/scene/fluid_output_section.hpp"
#include "fluid_app/output/macro_fields.hpp"
#include "fluid_app/stability/stability_diagnosis.hpp"

namespace lbdem {

struct StabilityFailure {
  InstabilityReport report;
  std::string last_good_file;  // empty when no check had passed before
  std::string message;         // describe_instability(...), identical on every rank
};

// The last good state: density and velocity as MacroFields holds them, rounded to float (a
// diagnostic snapshot; written as double on failure).
struct LastGoodFields {
  FieldBlock box;
  std::vector<float> rho;  // one per node
  std::vector<float> u;    // three per node

  void resize(const FieldBlock& b) {
    box = b;
    rho.resize(b.cells());
    u.resize(3 * b.cells());
  }
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
// Adds the scan of another part of the same rank's block (`global`: the global lattice), so
// that scanning a block in slabs gives what one scan of it gives.
void merge_scan(LocalScan& into, const LocalScan& part, const std::array<int, 3>& global);

class StabilityWatch {
 public:
  StabilityWatch(const StabilityParams& params, const UnitConverter& units, MPI_Comm comm,
                 std::string last_good_file);

  bool due(long step) const { return params_.interval > 0 && step % params_.interval == 0; }

  // Collective. nullopt: the state is fine and becomes last_good(); `fields` is left as it
  // was (a float copy is kept). Otherwise the same failure on every rank, after the last good
  // state was written collectively.
  std::optional<StabilityFailure> check(long step, double time, const MacroFields& fields);
  // The same for a state this rank scanned itself (`scan` over its block `box`): if every
  // rank's state is fine, keep(last_good) stores it into the fields given (sized to `box`).
  std::optional<StabilityFailure> check(long step, double time, const LocalScan& scan,
                                        const FieldBlock& box,
                                        const std::function<void(LastGoodFields&)>& keep);
  const LastGoodFields& last_good() const { return last_good_; }
  double max_mach() const { return params_.max_mach; }

 private:
  StabilityParams params_;
  UnitConverter units_;
  MPI_Comm comm_;
  std::string last_good_file_;
  LastGoodFields last_good_;
  long last_good_step_ = -1;
  double last_good_time_ = 0;
  double last_good_mach_ = 0;
};

}  // namespace lbdem
