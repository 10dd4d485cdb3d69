#pragma once
// The text LAMMPS reads to create the bodies: a data file with every clump sphere (atoms,
// body after body, tags 1..N in clump order, molecule ID = body id + 1) and the rigid-body
// `infile` with mass, centre of mass, space-frame inertia, velocity and angular momentum from
// the voxelized mass properties (mass = density x voxel volume).
#include <string>
#include <vector>

#include "dem_app/setup/dem_setup.hpp"

namespace lbdem {

// LAMMPS's rigid/small refuses one-particle bodies (it detects them by a zero bounding box),
// so a one-sphere clump gets tiny helper spheres (radius 1e-6 r) inside the real one: one at
// the centre of mass, or, when the sphere is centred within 1e-3 r of it, three at 1e-3 r
// from the sphere's centre along x, y and z. They never touch anything, so the contact law
// stays that of the one sphere, and the force weights can carry the external force through
// the centre of mass exactly with weights of order one.
Clump clump_for_lammps(const Clump& clump);

// The extent LAMMPS's rigid/small checks against the ghost cutoff ("Rigid body extent >
// ghost cutoff"), largest over the bodies in their current poses: it makes the sphere nearest
// the centre of the bounding box of a body's sphere centres (smallest tag on a tie) the
// body's owner and needs every sphere centre within the ghost cutoff of it. That is not the
// clump's reach from the centroid (clump_extent): for a ring the owner sits on the ring and
// the extent is nearly the ring's diameter. `setup` holds the clumps LAMMPS gets
// (clump_for_lammps).
double rigid_small_extent(const DemSetup& setup);

std::string lammps_data_file(const DemSetup& setup);
// `dt`: LAMMPS's set-up run leaves gravity out of the first half-kick (the rigid fix's
// `gravity` keyword acts from the first step on), which would shift every trajectory by
// -g dt/2 in velocity; the infile velocities carry +g dt/2 to cancel it exactly.
std::string lammps_rigid_infile(const DemSetup& setup, double dt);

// The commands that set up the system after the data file and infile are at `data_path`
// and `infile_path`; `pair_args` is the contact model's argument string.
std::vector<std::string> lammps_setup_commands(const DemSetup& setup, double dt,
                                               const std::string& pair_args,
                                               const std::string& data_path,
                                               const std::string& infile_path);

}  // namespace lbdem
