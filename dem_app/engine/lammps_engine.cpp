#include "dem_app/engine/lammps_engine.hpp"

#include <library.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "dem_app/engine/lammps_input.hpp"
#include "dem_app/engine/quaternion.hpp"
#include "dem_app/setup/lubrication_setup.hpp"

namespace lbdem {

namespace {

// fix external pf/callback. LAMMPS's step and tag types depend on its build (smallbig,
// bigbig), so the signature is deduced from the library's FixExternalFnPtr.
template <class Context, class Step, class Tag>
void external_callback(void* ptr, Step, int nlocal, Tag*, double**, double** fext) {
  auto* ctx = static_cast<Context*>(ptr);
  auto** torque = static_cast<double**>(lammps_extract_atom(ctx->lmp, "torque"));
  ctx->loads->apply(nlocal, static_cast<double**>(lammps_extract_atom(ctx->lmp, kLoadArray)), fext,
                    torque);
  if (!ctx->lubrication) return;
  // Ghosts too: a pair may straddle ranks or a periodic boundary.
  const int nall = nlocal + lammps_extract_setting(ctx->lmp, "nghost");
  const auto* all_tags = static_cast<const Tag*>(lammps_extract_atom(ctx->lmp, "id"));
  ctx->tags.assign(all_tags, all_tags + nall);
  ctx->lubrication->apply({nlocal, nall, ctx->tags.data(),
                           static_cast<double**>(lammps_extract_atom(ctx->lmp, "x")),
                           static_cast<double**>(lammps_extract_atom(ctx->lmp, "v")), fext,
                           static_cast<double**>(lammps_extract_atom(ctx->lmp, "omega")), torque});
}

template <class Context, class Step, class Tag>
FixExternalFnPtr callback_for(void (*)(void*, Step, int, Tag*, double**, double**)) {
  return &external_callback<Context, Step, Tag>;
}

// LAMMPS's tag type (also that of molecule IDs), from the same signature.
template <class Step, class Tag>
Tag tag_type(void (*)(void*, Step, int, Tag*, double**, double**));
using LammpsTag = decltype(tag_type(static_cast<FixExternalFnPtr>(nullptr)));

void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

// A fresh scratch directory made by rank 0, its name broadcast to all ranks.
std::string scratch_directory(MPI_Comm comm, int rank) {
  std::string path;
  if (rank == 0) {
    std::string tmpl = (std::filesystem::temp_directory_path() / "lbdem_dem_XXXXXX").string();
    if (!mkdtemp(tmpl.data())) throw std::runtime_error("cannot create a scratch directory");
    path = tmpl;
  }
  int n = static_cast<int>(path.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, comm);
  path.resize(static_cast<size_t>(n));
  MPI_Bcast(path.data(), n, MPI_CHAR, 0, comm);
  return path;
}

}  // namespace

LammpsEngine::LammpsEngine(MPI_Comm comm, DemSetup setup) : setup_(std::move(setup)) {
  validate_dem_setup(setup_);
  MPI_Comm_dup(comm, &comm_);
  MPI_Comm_dup(comm, &load_comm_);
  MPI_Comm_rank(comm_, &rank_);
  contact_ = make_contact_model(setup_.params.material, setup_.file);
  dt_ = dem_time_step(setup_);
  const std::vector<Shape> scene_shapes = setup_.shapes;
  for (auto& sh : setup_.shapes) sh.clump = clump_for_lammps(sh.clump);
  lubrication_ = make_lubrication(setup_, scene_shapes, setup_.shapes);
  for (const auto& b : setup_.bodies)
    mass_.push_back(b.density * setup_.shapes[static_cast<size_t>(b.shape)].mass.volume);
  build();
}

LammpsEngine::~LammpsEngine() {
  if (lmp_) lammps_close(lmp_);
  if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
  if (load_comm_ != MPI_COMM_NULL) MPI_Comm_free(&load_comm_);
}

void LammpsEngine::command(const std::string& c) const {
  lammps_command(lmp_, c.c_str());
}

std::int64_t LammpsEngine::step() const {
  return *static_cast<std::int64_t*>(lammps_extract_global(lmp_, "ntimestep"));
}

Eigen::Matrix3d LammpsEngine::body_inertia(std::int64_t id) const {
  const auto& b = setup_.bodies[static_cast<size_t>(id)];
  return b.density * setup_.shapes[static_cast<size_t>(b.shape)].mass.inertia;
}

void LammpsEngine::build() {
  const std::string dir = scratch_directory(comm_, rank_);
  const std::string data = dir + "/bodies.data", infile = dir + "/bodies.infile";
  if (rank_ == 0) {
    write_text(data, lammps_data_file(setup_));
    write_text(infile, lammps_rigid_infile(setup_, dt_));
  }
  MPI_Barrier(comm_);

  std::vector<std::string> args{"dem_app", "-screen", "none", "-log", setup_.lammps_log, "-nocite"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  lmp_ = lammps_open(static_cast<int>(argv.size()), argv.data(), comm_, nullptr);
  if (!lmp_) throw std::runtime_error("LAMMPS could not be started");

  for (const auto& c :
       lammps_setup_commands(setup_, dt_, contact_.lammps_arguments(), data, infile))
    command(c);
  if (setup_.external_loads) {
    int size = 1;
    MPI_Comm_size(comm_, &size);
    table_ = LoadTable(static_cast<std::int64_t>(setup_.bodies.size()), rank_, size);
    callback_ = {lmp_, &loads_, lubrication_.enabled() ? &lubrication_ : nullptr, {}};
    // Buoyancy -rho_f V g on every body, before the set-up's force evaluation so that the
    // first half-step of velocity carries it too.
    const double rho_f = setup_.buoyancy_density;
    if (rho_f > 0)
      for (size_t i = 0; i < setup_.bodies.size(); ++i) {
        const double volume =
            setup_.shapes[static_cast<size_t>(setup_.bodies[i].shape)].mass.volume;
        set_extra_force(static_cast<std::int64_t>(i),
                        -rho_f * volume * to_eigen(setup_.params.gravity));
      }
    set_atom_weights();
    exchange_atom_loads(true, {});  // the set-up's force evaluation below applies them too
    lammps_set_fix_external_callback(
        lmp_, "ext", callback_for<CallbackContext>(static_cast<FixExternalFnPtr>(nullptr)),
        &callback_);
  }
  // Set-up only (forces, body properties from the infile, initial quaternions); every later
  // run uses `pre no` so it neither re-derives the bodies nor loses half a step of gravity.
  command("run 0 post no");
  first_step_ = step();
  const auto* cols =
      static_cast<const int*>(lammps_extract_compute(lmp_, "rl", LMP_STYLE_LOCAL, LMP_SIZE_COLS));
  if (!cols || *cols != kRigidLocalCount)
    throw std::runtime_error("compute rigid/local does not have the expected columns");

  // q(0)^-1 q_user(0) for each body, from its owner, summed into every rank's table.
  const size_t n = setup_.bodies.size();
  std::vector<double> off(4 * n, 0.0), owners(n, 0.0);
  for (const auto& r : owned_records()) {
    const Eigen::Quaterniond o =
        r.q_lammps.normalized().conjugate() *
        to_eigen(setup_.bodies[static_cast<size_t>(r.id)].orientation).normalized();
    const auto i = static_cast<size_t>(r.id);
    off[4 * i] = o.w();
    off[4 * i + 1] = o.x();
    off[4 * i + 2] = o.y();
    off[4 * i + 3] = o.z();
    owners[i] += 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, off.data(), static_cast<int>(off.size()), MPI_DOUBLE, MPI_SUM, comm_);
  MPI_Allreduce(MPI_IN_PLACE, owners.data(), static_cast<int>(n), MPI_DOUBLE, MPI_SUM, comm_);
  for (size_t i = 0; i < n; ++i) {
    if (owners[i] != 1.0)
      throw std::runtime_error("LAMMPS reports body " + std::to_string(i) + " on " +
                               std::to_string(owners[i]) + " ranks after set-up");
    offset_.emplace_back(off[4 * i], off[4 * i + 1], off[4 * i + 2], off[4 * i + 3]);
  }
  MPI_Barrier(comm_);
  if (rank_ == 0) std::filesystem::remove_all(dir);
}

void LammpsEngine::set_load(std::int64_t id, const Eigen::Vector3d& force,
                            const Eigen::Vector3d& torque) {
  if (!setup_.external_loads)
    throw std::logic_error("set_load: the engine was built without external loads");
  pending_.push_back({id, 0, {force[0], force[1], force[2]}, {torque[0], torque[1], torque[2]}});
}

void LammpsEngine::set_extra_force(std::int64_t id, const Eigen::Vector3d& force) {
  if (!setup_.external_loads)
    throw std::logic_error("set_extra_force: the engine was built without external loads");
  if (id < 0 || static_cast<size_t>(id) >= body_count())
    throw std::out_of_range("extra force for unknown body " + std::to_string(id));
  if (table_.is_home(id)) table_.update({id, 1, {force[0], force[1], force[2]}, {0, 0, 0}});
}

void LammpsEngine::set_atom_weights() {
  // Atom tags are 1..N, body after body, in the order of the clump spheres (the data file);
  // the molecule ID is the body's index + 1.
  std::vector<std::vector<double>> weights;
  for (const auto& sh : setup_.shapes) weights.push_back(force_weights(sh.clump));
  std::vector<std::int64_t> first_tag;
  std::int64_t tag = 1;
  for (const auto& b : setup_.bodies) {
    first_tag.push_back(tag);
    tag += static_cast<std::int64_t>(weights[static_cast<size_t>(b.shape)].size());
  }
  const int nlocal = lammps_extract_setting(lmp_, "nlocal");
  const auto* tags = static_cast<const LammpsTag*>(lammps_extract_atom(lmp_, "id"));
  const auto* mol = static_cast<const LammpsTag*>(lammps_extract_atom(lmp_, "molecule"));
  auto** columns = static_cast<double**>(lammps_extract_atom(lmp_, kLoadArray));
  for (int i = 0; i < nlocal; ++i) {
    const auto b = static_cast<size_t>(mol[i] - 1);
    const auto& w = weights[static_cast<size_t>(setup_.bodies[b].shape)];
    columns[i][kWeight] = w[static_cast<size_t>(static_cast<std::int64_t>(tags[i]) - first_tag[b])];
    columns[i][kTorqueShare] = 1.0 / static_cast<double>(w.size());
  }
}

void LammpsEngine::exchange_atom_loads(bool fetch, LoadRun run) {
  const int nlocal = lammps_extract_setting(lmp_, "nlocal");
  const auto* mol = static_cast<const LammpsTag*>(lammps_extract_atom(lmp_, "molecule"));
  std::vector<std::int64_t> bodies;
  if (fetch)
    for (int i = 0; i < nlocal; ++i) bodies.push_back(static_cast<std::int64_t>(mol[i]) - 1);
  std::sort(bodies.begin(), bodies.end());
  bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
  const std::vector<AppliedLoad> loads =
      exchange_loads(pending_, bodies, table_, run, load_comm_, traffic_);
  pending_.clear();
  if (!fetch) return;
  auto** columns = static_cast<double**>(lammps_extract_atom(lmp_, kLoadArray));
  for (int i = 0; i < nlocal; ++i) {
    const auto at = std::lower_bound(bodies.begin(), bodies.end(), mol[i] - 1) - bodies.begin();
    write_applied(columns[i], loads[static_cast<size_t>(at)]);
  }
}

void LammpsEngine::run(long substeps) {
  if (setup_.external_loads) {
    // Loads set since the last run go to their homes; the spheres held here get their
    // bodies' loads in per-atom columns, which LAMMPS moves with an atom changing rank.
    exchange_atom_loads(substeps > 0, {substeps > 0, substeps >= 2});
    if (substeps > 0) loads_.begin_run(substeps);
  }
  if (substeps <= 0) return;
  command("run " + std::to_string(substeps) + " pre no post no");
}

std::vector<BodyRecord> LammpsEngine::owned_records() const {
  std::vector<BodyRecord> out;
  const auto* rows =
      static_cast<const int*>(lammps_extract_compute(lmp_, "rl", LMP_STYLE_LOCAL, LMP_SIZE_ROWS));
  if (!rows || *rows == 0) return out;
  auto** a =
      static_cast<double**>(lammps_extract_compute(lmp_, "rl", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY));
  for (int i = 0; i < *rows; ++i) out.push_back(record_from_row(a[i]));
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.id < y.id; });
  return out;
}

Eigen::Quaterniond LammpsEngine::user_orientation_of(const BodyRecord& r) const {
  return user_orientation(r.q_lammps, offset_[static_cast<size_t>(r.id)]);
}

std::int64_t LammpsEngine::local_atoms() const {
  return lammps_extract_setting(lmp_, "nlocal");
}

std::int64_t LammpsEngine::ghost_atoms() const {
  return lammps_extract_setting(lmp_, "nghost");
}

std::vector<BodyState> LammpsEngine::owned_states(std::int64_t fluid_step) const {
  std::vector<BodyState> out;
  for (const auto& r : owned_records()) {
    BodyState s;
    s.shape = setup_.bodies[static_cast<size_t>(r.id)].shape;
    s.id = r.id;
    s.step = fluid_step;
    const Eigen::Quaterniond q = user_orientation_of(r);
    const double qa[4] = {q.w(), q.x(), q.y(), q.z()};
    for (int d = 0; d < 3; ++d) {
      s.x[d] = r.x[d];
      s.v[d] = r.v[d];
      s.w[d] = r.omega[d];
    }
    for (int d = 0; d < 4; ++d) s.q[d] = qa[d];
    out.push_back(s);
  }
  return out;
}

DemEnergies LammpsEngine::energies() const {
  const Eigen::Vector3d g = to_eigen(setup_.params.gravity);
  double e[3] = {0, 0, 0};
  for (const auto& r : owned_records()) {
    const double m = mass_[static_cast<size_t>(r.id)];
    e[0] += 0.5 * m * r.v.squaredNorm();
    e[1] += 0.5 * r.omega.dot(r.angmom);
    e[2] -= m * g.dot(r.x_unwrapped);
  }
  MPI_Allreduce(MPI_IN_PLACE, e, 3, MPI_DOUBLE, MPI_SUM, comm_);
  DemEnergies out{e[0], e[1], e[2], 0};
  const auto* sum = static_cast<const double*>(
      lammps_extract_compute(lmp_, "ncontacts", LMP_STYLE_GLOBAL, LMP_TYPE_SCALAR));
  // contact/atom counts each touching pair once per sphere.
  if (sum) out.contacts = std::lround(*sum / 2.0);
  return out;
}

}  // namespace lbdem
