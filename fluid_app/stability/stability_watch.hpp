#pragma once
// The stability watch: every `interval` steps it scans the macroscopic state for non-finite
// values, non-positive density and Mach above the scene's limit. All fluid ranks agree on the
// outcome through reductions on the side communicator, so either every rank goes on or every
// rank stops with the same diagnosis. The last good state is kept on disk, not in memory: a
// check writes the state it scans, slab by slab, to a candidate file next to the last good one
// (density, velocity and pressure in float, the field file layout); when every rank passed,
// the candidate replaces the last good file, otherwise it is removed and the last good file is
// the one the diagnosis names. No rank holds more than one slab of the state, and a run killed
// at any moment still leaves a whole last good file (docs/performance.md "Memory per cell").
#include <mpi.h>

#include <functional>
#include <optional>
#include <string>

#include "coupler_lib/scene/fluid_output_section.hpp"
#include "fluid_app/output/macro_fields.hpp"
#include "fluid_app/stability/stability_diagnosis.hpp"

namespace lbdem {

struct StabilityFailure {
  InstabilityReport report;
  std::string last_good_file;  // empty when no check had passed before
  std::string message;         // describe_instability(...), identical on every rank
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

  // The state of the rank's local planes [z0, z1) (0-based), as a block of the global lattice.
  using Slabs = std::function<const MacroFields&(int z0, int z1)>;

  // Collective. Scans the rank's block `box`, `planes` planes at a time, writing each slab to
  // the candidate file as it goes. nullopt: every rank passed and the state is now the last
  // good file. Otherwise the same failure on every rank, naming the last good file (as the
  // last passing check left it).
  std::optional<StabilityFailure> check(long step, double time, const FieldBlock& box, int planes,
                                        const Slabs& slabs);
  // The same for a block the caller holds whole (one slab).
  std::optional<StabilityFailure> check(long step, double time, const MacroFields& fields);
  const std::string& last_good_file() const { return last_good_file_; }
  // After a run the watch did not stop: removes the last good file and its XDMF (rank 0), so
  // that a finished run leaves only the output its scene asks for.
  void remove_last_good() const;

 private:
  StabilityParams params_;
  UnitConverter units_;
  MPI_Comm comm_;
  std::string last_good_file_;
  long last_good_step_ = -1;
  double last_good_time_ = 0;
  double last_good_mach_ = 0;
};

}  // namespace lbdem
