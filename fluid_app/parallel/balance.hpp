#pragma once
// The work of the fluid lattice per slice of cells along each axis, for the balanced
// decomposition (fluid.decomposition: balanced, docs/scaling.md).
//
// A plain fluid cell costs 1; a cell a body covers (its band and interior, where the porosity,
// the penalization and the load sums run) costs fluid.covered_cell_weight. Each initial body
// is counted as its volume-equivalent sphere grown by 1.5 cells (the band's reach): its
// covered cells go to the slices it crosses in proportion to the sphere's cross-section,
// wrapped across periodic faces. The result feeds Decomposition, which cuts each axis where
// the cumulative work reaches equal shares.
#include <array>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/bodies_section.hpp"
#include "coupler_lib/scene/fluid_section.hpp"

namespace lbdem {

std::array<std::vector<double>, 3> body_work_weights(const FluidParams& fluid,
                                                     const std::vector<BodyParams>& bodies,
                                                     const std::vector<Shape>& shapes);

// The weighted work of a block: cells + (covered_cell_weight - 1) x covered cells.
inline double weighted_work(double cells, double covered, double covered_cell_weight) {
  return cells + (covered_cell_weight - 1) * covered;
}

}  // namespace lbdem
