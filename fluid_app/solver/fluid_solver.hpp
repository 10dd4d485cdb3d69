#pragma once
// D3Q19 BGK lattice Boltzmann solver on one rank's block of a uniform grid.
//
// One step = fused collide + stream over the rank's cells (AA pattern, in place, see
// fluid_app/kernel/aa_kernel.hpp), halo exchange with the neighbour ranks (overlapped with the
// inner cells' work), then the boundary links of non-periodic faces. After step() returns the
// lattice holds the post-stream, pre-collision populations of the next step; every accessor
// below hides the AA storage parity.
//
// Everything is in LATTICE units (dx = dt = 1, reference density 1); FluidParams::units
// converts. Template on the floating type: FluidSolver<double> (default) and
// FluidSolver<float> are the same code.
#include <mpi.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "coupler_lib/scene/fluid_section.hpp"
#include "fluid_app/lattice/local_box.hpp"
#include "fluid_app/parallel/decomposition.hpp"
#include "fluid_app/parallel/halo_exchange.hpp"
#include "fluid_app/porous_field.hpp"

namespace lbdem {

// Mean fluid velocity over the whole domain, weighted by porosity d (1 in fluid) and density:
// u_mean = sum(d rho u*) / sum(d rho), u* the physical velocity (docs/method.md Eq. (6)).
// Sums are exact (fixed point) so the result does not depend on the rank count.
struct MeanFlow {
  std::array<double, 3> velocity{};  // lattice units
  double mass = 0;                   // sum(d rho), lattice units
};

// What the solver carries from one step to the next besides the populations and the porous
// field (which the HLBM rebuilds from the body states): what a checkpoint stores.
struct SolverMemory {
  std::int64_t steps = 0;
  std::array<double, 3> force{};    // uniform force of the next step (uniform_force())
  std::array<double, 3> impulse{};  // applied_impulse()
  MeanFlow mean;                    // mean_flow()
};

template <class T>
class FluidSolverImpl;

template <class T>
class FluidSolver {
 public:
  // Collective over `comm` (the side communicator of fluid_app). Starts at rest, rho = 1.
  // `dims` forces the process grid (0 = automatic), for tests.
  // `weights`: the work per slice of cells along each axis (balance.hpp) for a balanced split.
  FluidSolver(const FluidParams& params, MPI_Comm comm, std::array<int, 3> dims = {0, 0, 0},
              const std::array<std::vector<double>, 3>& weights = {});
  ~FluidSolver();
  FluidSolver(const FluidSolver&) = delete;
  FluidSolver& operator=(const FluidSolver&) = delete;

  // One time step (collective). Uses the current uniform force and porous field.
  void step();
  std::int64_t steps() const;

  const LocalBox& box() const;
  const Decomposition& decomposition() const;
  MPI_Comm comm() const;  // the Cartesian communicator (same ranks as the one given)
  // What this rank sent to its neighbours in the halo exchanges so far (one per step).
  const HaloTraffic& halo_traffic() const;

  // --- State after the last step (post-stream, pre-collision), any AA parity. ---
  // Population i at a local cell. Valid for every interior cell, and for a ghost cell for
  // each i whose source cell (cell - c_i) is interior: together, both populations of every
  // lattice link with at least one interior end, which is what momentum exchange needs.
  T population(int i, CellIndex cell) const;
  T density(CellIndex cell) const;  // interior cells
  // Physical velocity u* = v + F/(2 rho) + (1-d)(u_p - v)/2 with the current force and
  // porous field (docs/method.md Eq. (6)). Interior cells.
  std::array<T, 3> velocity(CellIndex cell) const;
  // Density and physical velocity of all interior cells, x fastest; u interleaved (3 per cell).
  void macroscopic(std::vector<T>& rho, std::vector<T>& u) const;
  // Overwrite one interior cell with the equilibrium at (rho, u) (initial conditions).
  void set_equilibrium(CellIndex cell, T rho, std::array<T, 3> u);

  // --- Checkpoints. ---
  // The post-stream populations of this rank's interior cells, population-major, then cells
  // x fastest (the rank's block of the global array [19][nz][ny][nx]), whatever the AA parity.
  void interior_populations(std::vector<T>& out) const;
  // The reverse, after restore(memory) has set the step count (and with it the AA parity):
  // every location the next step reads is written, so the run continues bit for bit.
  void set_interior_populations(const std::vector<T>& in);
  SolverMemory memory() const;
  void restore(const SolverMemory& m);

  // --- Forcing. ---
  // Uniform body force density F (lattice units; momentum added per cell and step is F),
  // applied from the next step on until replaced. It starts as fluid.body_force; whoever
  // drives it (the mean-velocity controller, fluid_app/forcing/mean_flow_control.hpp; the
  // coupled run's settling force) sets it between steps.
  void set_uniform_force(std::array<double, 3> force);
  std::array<double, 3> uniform_force() const;
  // Sum over the steps taken of the uniform force on all nodes of the domain, F * N (lattice
  // units: the momentum the force gave the lattice), whatever set it (scene, feed-forward,
  // controller). The momentum audit compares momentum changes with it.
  std::array<double, 3> applied_impulse() const;
  // Lattice momentum sum_i c_i f_i over all nodes (post-stream, the bare moment j; collective).
  std::array<double, 3> momentum() const;
  // Mean flow measured during the last step (only maintained after measure_mean_flow(true),
  // which the mean-velocity controller calls).
  MeanFlow mean_flow() const;
  void measure_mean_flow(bool on);

  // The porosity field (allocated on first call: d = 1, body = -1, inactive).
  PorousField<T>& porous();
  const PorousField<T>& porous() const;
  // Cells of the rows (along x, as the kernel splits this rank's block: the inner cells and the
  // shell around them) that take a porous path with the porous field as it is now: rows with a
  // covered cell (porous_row, fluid_app/kernel/aa_kernel.hpp). 0 while the field is inactive.
  double porous_row_cells() const;

  // Bytes the kernel moves per cell update: 2 * 19 * sizeof(T) (+ 8 with the porous field).
  static constexpr int bytes_per_cell_update(bool porous) {
    return 2 * 19 * int(sizeof(T)) + (porous ? 8 : 0);
  }

 private:
  std::unique_ptr<FluidSolverImpl<T>> impl_;
};

extern template class FluidSolver<double>;
extern template class FluidSolver<float>;

}  // namespace lbdem
