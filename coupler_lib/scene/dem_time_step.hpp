#pragma once
// The DEM time step rule of a scene (paper, table of hindered-settling parameters): dem.dt when
// given, else dem.dt_fraction times the smallest Rayleigh time over the bodies. Lives in the
// scene layer so that both programs (dem_app runs it, fluid_app reports it in the resolved
// scene) take it from one place.
#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/bodies_section.hpp"
#include "coupler_lib/scene/dem_section.hpp"

namespace lbdem {

// Rayleigh time of a sphere of radius r:
//   t_R = pi r / beta sqrt(rho / G),  G = E / (2 (1 + nu)),  beta = 0.8766 + 0.1630 nu.
double rayleigh_time(double radius, double density, const DemMaterial& m);

// Smallest clump-sphere radius of a shape.
double smallest_sphere_radius(const Shape& shape);

// Radius whose Rayleigh time sets the DEM step for a body of this shape (dem.dt_rule): the
// smallest clump sphere, or the volume-equivalent sphere of the body.
double time_step_radius(const Shape& shape, const DemParams& params);

// Smallest Rayleigh time over the bodies (infinite without bodies).
double smallest_rayleigh_time(const DemParams& params, const std::vector<Shape>& shapes,
                              const std::vector<BodyParams>& bodies);

// DEM step: dem.dt if given, else dt_fraction x smallest_rayleigh_time.
double dem_time_step(const DemParams& params, const std::vector<Shape>& shapes,
                     const std::vector<BodyParams>& bodies);

}  // namespace lbdem
