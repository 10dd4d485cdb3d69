#pragma once
// Body routing: which fluid ranks a body can touch.
//
// A fluid rank needs a body when the body's bounding sphere, grown by the stencil margin
// (coupling.margin fluid cells times dx: the porosity of a node averages over its q-1
// neighbours and the momentum exchange reads links one cell out), comes within reach of the
// rank's subdomain box, for the body itself or any of its periodic images. The test is the
// exact sphere-box distance, so a body near a box corner is not sent to a rank it misses.
#include <array>
#include <span>
#include <vector>

namespace lbdem {

// Axis-aligned box, SI (m): [lo, hi] along each axis.
struct Box {
  std::array<double, 3> lo{};
  std::array<double, 3> hi{};
};

// What the fluid side announces at start: its decomposition and how far bodies reach.
struct FluidLayout {
  Box domain;                        // the whole fluid box
  std::array<bool, 3> periodic{};    // periodic axes of the fluid box
  std::vector<Box> boxes;            // subdomain of each fluid rank, by rank
  std::vector<double> shape_radius;  // bounding radius of each catalogue shape, m
  double margin = 0;                 // stencil margin, m

  double reach(int shape) const;  // bounding radius of the shape plus the margin
};

// Squared distance from `x` to `box`, minimised over the periodic images of `x`.
double periodic_distance2(const FluidLayout& layout, const Box& box, const double x[3]);

// Fluid ranks (ascending, each once) whose box lies within `reach` of `x` or of one of its
// periodic images. `x` need not be wrapped into the domain.
std::vector<int> touched_ranks(const FluidLayout& layout, const double x[3], double reach);

// Throws std::invalid_argument naming the first problem (empty box, box outside the domain,
// negative radius, ...).
void validate_layout(const FluidLayout& layout);

// Flat form for sending over MPI and storing in a recording.
std::vector<double> pack_layout(const FluidLayout& layout);
FluidLayout unpack_layout(std::span<const double> flat);

}  // namespace lbdem
