#include "dem_app/engine/lammps_input.hpp"

#include <cmath>
#include <sstream>

#include "dem_app/engine/body_state.hpp"
#include "dem_app/engine/quaternion.hpp"
#include "dem_app/external_load.hpp"

namespace lbdem {

namespace {

std::ostringstream precise() {
  std::ostringstream s;
  s.precision(17);
  return s;
}

// Largest clump-sphere radius over the shapes that bodies use.
double largest_sphere_radius(const DemSetup& setup) {
  double r = 0;
  for (const auto& b : setup.bodies)
    for (double ri : setup.shapes[static_cast<size_t>(b.shape)].clump.radii) r = std::max(r, ri);
  return r;
}

}  // namespace

double rigid_small_extent(const DemSetup& setup) {
  double extent = 0;
  for (const auto& b : setup.bodies) {
    const Clump& clump = setup.shapes[static_cast<size_t>(b.shape)].clump;
    const Eigen::Matrix3d rot = to_eigen(b.orientation).normalized().toRotationMatrix();
    // The sphere centres exactly as lammps_data_file writes them.
    std::vector<Eigen::Vector3d> x;
    for (const auto& c : clump.centers) x.push_back(to_eigen(b.position) + rot * c);
    Eigen::Vector3d lo = x[0], hi = x[0];
    for (const auto& xi : x) {
      lo = lo.cwiseMin(xi);
      hi = hi.cwiseMax(xi);
    }
    const Eigen::Vector3d centre = 0.5 * (lo + hi);
    // The first sphere (smallest tag) among the nearest ones owns the body.
    size_t owner = 0;
    for (size_t k = 1; k < x.size(); ++k)
      if ((x[k] - centre).squaredNorm() < (x[owner] - centre).squaredNorm()) owner = k;
    for (const auto& xi : x) extent = std::max(extent, (xi - x[owner]).norm());
  }
  return extent;
}

Clump clump_for_lammps(const Clump& clump) {
  Clump c = clump;
  if (c.centers.size() == 1) {
    const double tiny = 1e-6 * c.radii[0], offset = 1e-3 * c.radii[0];
    const Eigen::Vector3d p = c.centers[0];
    if (p.norm() >= offset) {
      c.centers.push_back(Eigen::Vector3d::Zero());
      c.radii.push_back(tiny);
    } else {
      for (int d = 0; d < 3; ++d) {
        c.centers.push_back(p + offset * Eigen::Vector3d::Unit(d));
        c.radii.push_back(tiny);
      }
    }
  }
  return c;
}

std::string lammps_data_file(const DemSetup& setup) {
  size_t natoms = 0;
  for (const auto& b : setup.bodies)
    natoms += setup.shapes[static_cast<size_t>(b.shape)].clump.centers.size();
  auto s = precise();
  s << "lbdem bodies\n\n" << natoms << " atoms\n1 atom types\n\n";
  const char* lohi[3] = {"xlo xhi", "ylo yhi", "zlo zhi"};
  for (int d = 0; d < 3; ++d)
    s << setup.box_lo[d] << " " << setup.box_hi[d] << " " << lohi[d] << "\n";
  s << "\nAtoms # sphere\n\n";
  long tag = 1;
  for (const auto& b : setup.bodies) {
    const Shape& sh = setup.shapes[static_cast<size_t>(b.shape)];
    const Eigen::Matrix3d rot = to_eigen(b.orientation).normalized().toRotationMatrix();
    for (size_t k = 0; k < sh.clump.centers.size(); ++k) {
      const Eigen::Vector3d x = to_eigen(b.position) + rot * sh.clump.centers[k];
      // Per-sphere mass is irrelevant: the rigid fix takes mass and inertia from the infile.
      s << tag++ << " 1 " << 2 * sh.clump.radii[k] << " " << b.density << " " << x[0] << " " << x[1]
        << " " << x[2] << "\n";
    }
  }
  s << "\nMolecules\n\n";
  tag = 1;
  for (size_t i = 0; i < setup.bodies.size(); ++i) {
    const auto n = setup.shapes[static_cast<size_t>(setup.bodies[i].shape)].clump.centers.size();
    for (size_t k = 0; k < n; ++k) s << tag++ << " " << i + 1 << "\n";
  }
  return s.str();
}

std::string lammps_rigid_infile(const DemSetup& setup, double dt) {
  auto s = precise();
  const Eigen::Vector3d kick =
      0.5 * dt *
      Eigen::Vector3d(setup.params.gravity[0], setup.params.gravity[1], setup.params.gravity[2]);
  s << setup.bodies.size() << "\n";
  for (size_t i = 0; i < setup.bodies.size(); ++i) {
    const auto& b = setup.bodies[i];
    const Shape& sh = setup.shapes[static_cast<size_t>(b.shape)];
    const Eigen::Matrix3d rot = to_eigen(b.orientation).normalized().toRotationMatrix();
    const double mass = b.density * sh.mass.volume;
    const Eigen::Matrix3d inertia = b.density * rot * sh.mass.inertia * rot.transpose();
    const Eigen::Vector3d angmom = inertia * to_eigen(b.angular_velocity);
    const Eigen::Vector3d v = to_eigen(b.velocity) + kick;
    // ID mass xcm ycm zcm ixx iyy izz ixy ixz iyz vx vy vz lx ly lz ix iy iz (space frame)
    s << i + 1 << " " << mass << " " << b.position[0] << " " << b.position[1] << " "
      << b.position[2] << " " << inertia(0, 0) << " " << inertia(1, 1) << " " << inertia(2, 2)
      << " " << inertia(0, 1) << " " << inertia(0, 2) << " " << inertia(1, 2) << " " << v[0] << " "
      << v[1] << " " << v[2] << " " << angmom[0] << " " << angmom[1] << " " << angmom[2]
      << " 0 0 0\n";
  }
  return s.str();
}

std::vector<std::string> lammps_setup_commands(const DemSetup& setup, double dt,
                                               const std::string& pair_args,
                                               const std::string& data_path,
                                               const std::string& infile_path) {
  const auto& p = setup.params;
  std::vector<std::string> c;
  auto s = precise();
  c.push_back("units si");
  c.push_back("atom_style sphere");
  c.push_back("atom_modify map array");
  // Non-periodic axes shrink-wrap (with the scene box as minimum), so a body leaving an open
  // side never becomes a "lost atom" error that would end the process.
  std::string boundary = "boundary";
  for (int d = 0; d < 3; ++d) boundary += p.periodic[d] ? " p" : " m";
  c.push_back(boundary);
  s << "region box block " << setup.box_lo[0] << " " << setup.box_hi[0] << " " << setup.box_lo[1]
    << " " << setup.box_hi[1] << " " << setup.box_lo[2] << " " << setup.box_hi[2] << " units box";
  c.push_back(s.str());
  c.push_back("create_box 1 box");
  c.push_back("fix prop all property/atom mol ghost yes");
  // What fix external applies to each sphere (dem_app/external_load.hpp), moved with it.
  if (setup.external_loads)
    c.push_back(std::string("fix lbdemload all property/atom ") + kLoadArray + " " +
                std::to_string(kLoadColumns));
  c.push_back("read_data " + data_path + " add append fix prop NULL Molecules");

  // Ghost atoms must reach a whole body: rigid/small checks its own extent (from the owning
  // sphere) against the ghost cutoff; the clump's reach from the centroid is the older bound,
  // kept where it is the larger so that those inputs stay as they were.
  double extent = rigid_small_extent(setup);
  for (const auto& b : setup.bodies)
    extent = std::max(extent, clump_extent(setup.shapes[static_cast<size_t>(b.shape)]));
  const double skin = p.neighbor_skin > 0 ? p.neighbor_skin : 0.5 * largest_sphere_radius(setup);
  // The lubrication correction pairs clump spheres up to h_c apart from ghosts too.
  if (p.lubrication.enabled)
    extent = std::max(extent, 2 * largest_sphere_radius(setup) + p.lubrication.cutoff);
  s = precise();
  s << "comm_modify vel yes cutoff " << extent + skin;
  c.push_back(s.str());
  c.push_back("pair_style granular");
  c.push_back("pair_coeff * * " + pair_args);
  s = precise();
  s << "neighbor " << skin << " bin";
  c.push_back(s.str());
  // Spheres of one body overlap; without the exclusion LAMMPS computes (and the rigid fix
  // cancels) all those forces, ~8x slower.
  c.push_back("neigh_modify delay 0 every 1 check yes exclude molecule/intra all");
  s = precise();
  s << "timestep " << dt;
  c.push_back(s.str());

  const Eigen::Vector3d g = to_eigen(p.gravity);
  const bool gravity = g.norm() > 0;
  if (gravity) {
    // Gravity acts on the body mass from the infile (the `gravity` keyword of the rigid fix),
    // not on the summed sphere masses; `disable` stops the fix from acting on atoms itself.
    s = precise();
    s << "fix grav all gravity " << g.norm() << " vector " << g[0] / g.norm() << " "
      << g[1] / g.norm() << " " << g[2] / g.norm() << " disable";
    c.push_back(s.str());
  }
  // Fixes that add forces come before the rigid fix, so that the rigid fix's set-up sums them.
  if (setup.external_loads) c.push_back("fix ext all external pf/callback 1 1");
  for (size_t w = 0; w < p.walls.size(); ++w) {
    const auto& wall = p.walls[w];
    const int d = wall.axis;
    s = precise();
    s << wall.position.value_or(wall.lower ? setup.box_lo[d] : setup.box_hi[d]);
    const std::string pos = s.str();
    c.push_back("fix wall" + std::to_string(w) + " all wall/gran granular " + pair_args + " " +
                axis_name(d) + "plane " + (wall.lower ? pos + " NULL" : "NULL " + pos));
  }
  c.push_back("fix rigid all rigid/small molecule infile " + infile_path +
              (gravity ? " gravity grav" : ""));
  c.push_back(std::string("compute rl all rigid/local rigid ") + kRigidLocalColumns);
  c.push_back("compute contacts all contact/atom");
  c.push_back("compute ncontacts all reduce sum c_contacts");
  // The default thermo fails with rigid bodies; keep it minimal (re-evaluated every run).
  c.push_back("thermo_style custom step");
  c.push_back("thermo 0");
  return c;
}

}  // namespace lbdem
