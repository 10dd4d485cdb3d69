#pragma once
// The resolved scene as JSON, what `fluid_app --check --json` and `dem_app --check --json` print
// (docs/user-guide.md, "The resolved scene as JSON"). One implementation for both programs, so
// they print the same text for the same scene, and the one source of truth for the Python tools
// (tools/lbdem/scene.py), which therefore read a scene exactly as the programs do.
//
//   {"format": "lbdem-resolved-scene", "version": 1, "file": ..., "hash": ...,
//    "scene":   every key the programs read, defaults filled in, SI units, nested as in the YAML
//               (bodies: the entries as written: single bodies, generators, files),
//    "derived": lattice units (dx, dt, tau, nu_lattice, cells, ...), the DEM box and step, the
//               schedule (steps, substeps, intervals in steps), body totals,
//    "shapes":  per shape its volume, bounding radius, clump and principal moments,
//    "bodies":  every body after generators and files are expanded, with shape, mass, volume}
#include <string>

#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

// Builds the scene's shapes (as both programs do at start-up); throws SceneError like them.
std::string scene_json(const Scene& scene);

}  // namespace lbdem
