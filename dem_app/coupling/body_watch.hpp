#pragma once
// The DEM side of the coupled stability watch (docs/stability.md, "Coupled stability watch").
// After every exchange the bodies are checked for
//   * a non-finite position, orientation, velocity or angular velocity;
//   * a velocity blow-up: the fastest point of a body, |v| + |omega| r_bound, above the
//     fluid's Mach limit (fluid.stability.max_mach) times the lattice sound speed
//     c_s = dx / (sqrt(3) dt): the penalization can no longer follow the body;
//   * a contact overlap of two bodies' clump spheres deeper than dem.max_overlap times the
//     smaller sphere radius: the contact is too soft or too stiff for the DEM step.
// The fluid side watches its own state (fluid_app/stability/stability_watch.hpp); both programs
// then agree at the exchange and stop together (coupled_dem.cpp, coupled_fluid.cpp).
#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/scene/scene.hpp"
#include "dem_app/setup/dem_setup.hpp"

namespace lbdem {

struct BodyWatchLimits {
  double max_speed = 0;    // m/s, 0: no check
  double max_overlap = 0;  // fraction of the smaller clump-sphere radius, 0: no check
};

BodyWatchLimits body_watch_limits(const Scene& scene);

// Collective over `side`: the diagnosis (what, where, when, likely cause, what to change), the
// same on every rank, or an empty string when the bodies are fine. Non-finite states and speeds
// are checked always (cheap, every step: each rank its own bodies, the first finding in rank
// order reported), the clump overlap search only with `overlaps` (at the steps both programs
// agree, stop_request.hpp: it gathers all bodies on rank 0 and searches neighbouring pairs).
std::string check_bodies(const std::vector<BodyState>& owned, std::int64_t step, double time,
                         const DemSetup& setup, const BodyWatchLimits& limits, bool overlaps,
                         MPI_Comm side);

}  // namespace lbdem
