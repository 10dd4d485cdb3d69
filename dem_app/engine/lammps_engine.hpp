#pragma once
// The DEM engine: one LAMMPS instance (used as a library, unmodified) holding the rigid
// multi-sphere bodies of a scene, with the contact law, walls, gravity and external loads.
//
// What a coupled driver does with it, once per fluid step:
//   engine.set_load(id, F, T) for the bodies the coupler delivered (any rank may call it;
//   each load goes to the DEM ranks holding the body's spheres inside run(),
//   dem_app/load_routing.hpp), engine.run(n_dem),
//   engine.owned_states(step) -> BodyState packets of the bodies this rank owns.
// Everything else (box, clumps, mass properties, contact model, time step) comes from the
// DemSetup. All calls that run LAMMPS are collective over the engine's communicator.
#include <mpi.h>

#include <Eigen/Dense>

#include <cstdint>
#include <string>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "dem_app/contact/contact_model.hpp"
#include "dem_app/engine/body_state.hpp"
#include "dem_app/external_load.hpp"
#include "dem_app/load_routing.hpp"
#include "dem_app/load_table.hpp"
#include "dem_app/lubrication/lubrication.hpp"
#include "dem_app/setup/dem_setup.hpp"

namespace lbdem {

// Sums over all bodies (SI). Potential energy is -m g . x with unwrapped positions.
struct DemEnergies {
  double kinetic_translational = 0;
  double kinetic_rotational = 0;
  double potential = 0;
  long contacts = 0;  // touching clump-sphere pairs of different bodies (walls not counted)
};

class LammpsEngine {
 public:
  // Validates the setup (SceneError), then builds the LAMMPS system and runs its set-up.
  LammpsEngine(MPI_Comm comm, DemSetup setup);
  ~LammpsEngine();
  LammpsEngine(const LammpsEngine&) = delete;
  LammpsEngine& operator=(const LammpsEngine&) = delete;

  const DemSetup& setup() const { return setup_; }
  const ContactModel& contact_model() const { return contact_; }
  double dt() const { return dt_; }
  std::int64_t step() const;
  double time() const { return static_cast<double>(step() - first_step_) * dt_; }
  std::size_t body_count() const { return setup_.bodies.size(); }
  double body_mass(std::int64_t id) const { return mass_[static_cast<size_t>(id)]; }
  // Inertia tensor about the centre of mass in the shape frame, kg m^2.
  Eigen::Matrix3d body_inertia(std::int64_t id) const;

  // Hydrodynamic (or any) force and torque about the centre of mass, held constant until
  // replaced. Takes effect at the next run(). Needs setup.external_loads.
  void set_load(std::int64_t id, const Eigen::Vector3d& force, const Eigen::Vector3d& torque);
  // An additional constant force (e.g. buoyancy), held until replaced: called on every rank
  // with the same force (only the body's home rank keeps it, without communication).
  void set_extra_force(std::int64_t id, const Eigen::Vector3d& force);
  // What this rank received in the load exchanges so far (payload and message sizes).
  const LoadTraffic& load_traffic() const { return traffic_; }
  // The sub-grid lubrication correction (docs/lubrication.md); disabled unless the scene asks.
  const Lubrication& lubrication() const { return lubrication_; }

  // Advances n DEM steps (collective).
  void run(long substeps);

  // Bodies owned by this rank (LAMMPS's rigid/small ownership), sorted by id.
  std::vector<BodyRecord> owned_records() const;
  // The same as packets, orientation in the shape frame.
  std::vector<BodyState> owned_states(std::int64_t fluid_step) const;
  // Clump spheres this rank owns and holds as ghosts now.
  std::int64_t local_atoms() const;
  std::int64_t ghost_atoms() const;
  Eigen::Quaterniond user_orientation_of(const BodyRecord& r) const;

  DemEnergies energies() const;  // collective
  MPI_Comm comm() const { return comm_; }
  void* handle() const { return lmp_; }

 private:
  void command(const std::string& c) const;
  void build();
  // Sends the pending loads to their homes and, with `fetch`, writes for each local atom
  // what the run applies to its body (asked from the homes); collective.
  void exchange_atom_loads(bool fetch, LoadRun run);
  void set_atom_weights();

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  DemSetup setup_;
  ContactModel contact_;
  double dt_ = 0;
  void* lmp_ = nullptr;
  std::int64_t first_step_ = 0;
  std::vector<double> mass_;
  std::vector<Eigen::Quaterniond> offset_;  // q_lammps(0)^-1 q_user(0) per body
  MPI_Comm load_comm_ = MPI_COMM_NULL;      // the load exchange's own messages
  LoadTable table_;
  ExternalLoads loads_;
  LoadTraffic traffic_;
  Lubrication lubrication_;
  struct CallbackContext {
    void* lmp = nullptr;
    ExternalLoads* loads = nullptr;
    Lubrication* lubrication = nullptr;  // null when disabled
    std::vector<std::int64_t> tags;      // scratch: local and ghost tags as 64 bit
  } callback_;
  std::vector<LoadUpdate> pending_;  // loads set since the last run
};

}  // namespace lbdem
