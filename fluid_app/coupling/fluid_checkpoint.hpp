#pragma once
// The fluid half of a checkpoint (docs/reliability.md, "Checkpoint and restart"): one HDF5
// file written by all fluid ranks together (MPI-IO), readable by any number of fluid ranks.
//
//   populations       [19][nz][ny][nx] in the run's precision: the post-stream populations
//                     of the whole lattice, each rank writing its block (the global layout,
//                     so a restart may use another decomposition). Memory: one extra copy of
//                     the rank's interior populations while writing; file: 19 x 8 B per cell
//                     in double (4 B in float).
//   solver_memory     step count, uniform force, the mean-velocity controller's integral,
//                     applied impulse, mean flow (SolverMemory and MeanFlowControl::integral).
//   covered           per fluid rank and body: the covered fluid momentum Q and moment L of
//                     the last step, which the next penalization load differences against.
//   measured_work_{x,y,z}, layout_weights_{x,y,z}
//                     the work of the lattice per slice of cells measured at the checkpoint and
//                     the slice weights its cuts came from (absent: regular blocks), for a
//                     restart's layout (fluid_app/parallel/rebalance.hpp).
//   attributes        the checkpoint header, a checksum of the populations, the length of the
//                     CSV series at the checkpoint (series, momentum audit), and the load
//                     imbalance of the measured work.
// The porosity field is not stored: it is rebuilt from the body states of the checkpoint's
// step, which the DEM side sends again at the restart.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "coupler_lib/coupling/checkpoint_files.hpp"
#include "fluid_app/parallel/rebalance.hpp"
#include "fluid_app/solver/fluid_solver.hpp"

namespace lbdem {

// Q and L of one body on one fluid rank (lattice units).
struct CoveredRecord {
  std::int64_t rank = 0;
  std::int64_t id = 0;
  std::array<double, 3> covered{}, covered_moment{}, centre{};  // Q, L and the centre L is about
};

struct SeriesLengths {
  long long series = -1;    // bytes of <name>_series.csv (-1: none)
  long long momentum = -1;  // bytes of <name>_momentum.csv (-1: none)
};

// Collective over the solver's ranks: writes fluid_half(prefix) through a temporary name.
// `control_integral`: the mean-velocity controller's (zero without one).
template <class T>
void write_fluid_checkpoint(const std::string& prefix, const CheckpointHeader& header,
                            const FluidSolver<T>& solver,
                            const std::array<double, 3>& control_integral,
                            std::span<const CoveredRecord> mine, const SeriesLengths& lengths,
                            const CheckpointWork& work);

// Collective: the work and layout record of fluid_half(prefix), before the solver is built.
// Throws std::runtime_error naming the file when it is unreadable.
CheckpointWork read_checkpoint_work(const std::string& prefix, MPI_Comm comm);

struct FluidRestart {
  CheckpointHeader header;
  SolverMemory memory;                       // to restore after the run's own set-up of forces
  std::array<double, 3> control_integral{};  // MeanFlowControl::restore
  std::vector<CoveredRecord> covered;        // every rank's records of the stopped run
  SeriesLengths lengths;
};

// Collective: checks the header against `expected`, reads this rank's block of populations
// into `populations` (for FluidSolver::set_interior_populations, after restore(memory)) and
// verifies the checksum. Throws std::runtime_error naming the file and what to do when the
// file is unreadable, of another scene or version, or corrupted.
template <class T>
FluidRestart read_fluid_checkpoint(const std::string& prefix, const CheckpointHeader& expected,
                                   const FluidSolver<T>& solver, std::vector<T>& populations);

}  // namespace lbdem
