#pragma once
// Glue between a BodyField and the fluid solver it feeds: the rank's subdomain as the HLBM
// operators see it, and the post-stream population accessor the momentum exchange reads.
#include "coupler_lib/scene/fluid_section.hpp"
#include "fluid_app/hlbm/subdomain.hpp"
#include "fluid_app/solver/fluid_solver.hpp"

namespace lbdem::hlbm {

template <class T>
Subdomain subdomain_of(const FluidSolver<T>& solver, const FluidParams& params) {
  return {solver.box(), {params.periodic(0), params.periodic(1), params.periodic(2)}};
}

// f(i, cell) for hlbm::momentum_exchange; the solver must outlive the accessor.
template <class T>
auto populations_of(const FluidSolver<T>& solver) {
  return [&solver](int i, CellIndex cell) { return solver.population(i, cell); };
}

}  // namespace lbdem::hlbm
