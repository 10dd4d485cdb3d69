#pragma once
// The analytic solution a validation scene is compared with, set up from the scene's own
// boundaries and forcing (so the scene cannot say one thing and check another):
//   poiseuille:   walls (at rest) on both faces of one axis, the other axes periodic, a body
//                 force along the walls; the transient from rest (channel_flow.hpp);
//   couette:      walls on both faces of one axis, at least one moving, no body force;
//   taylor_green: triply periodic, no force, square in the vortex plane; the run starts from
//                 the solution at t = 0 (velocity and pressure).
// A scene that does not fit its case is refused with a SceneError naming the file and key.
#include <array>
#include <functional>
#include <string>

#include "coupler_lib/scene/fluid_output_section.hpp"
#include "coupler_lib/scene/fluid_section.hpp"

namespace lbdem {

struct ReferenceSolution {
  std::string description;  // one line with the case's parameters, for the log
  // SI velocity at SI position x and time t.
  std::function<std::array<double, 3>(const std::array<double, 3>& x, double t)> velocity;
  // SI pressure relative to the reference state; set only when the run must start from the
  // solution (taylor_green).
  std::function<double(const std::array<double, 3>& x, double t)> initial_pressure;
};

ReferenceSolution make_reference(const FluidParams& fluid, const ValidationParams& v,
                                 const std::string& scene_file);

}  // namespace lbdem
