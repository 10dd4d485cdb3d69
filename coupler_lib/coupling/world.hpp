#pragma once
// The coupled world: the intercommunicator between the fluid program and the DEM program,
// and the handshake that makes sure the right two programs are talking.
//
// Both binaries call connect() right after run_app's set-up when the scene is coupled
// (Scene::coupled()) and they are not replaying. The handshake checks, on every rank of both
// programs alike (so the job ends with one message and exit status 1):
//   * two programs were launched (not one, not three), with the exact mpirun line to use;
//   * one is the fluid side and the other the DEM side (not fluid_app : fluid_app);
//   * both speak the same coupling protocol version (kProtocolVersion);
//   * both read the same scene (Scene::hash of the file bytes).
// A program that never reaches the handshake (it crashed, or finished without coupling)
// makes the other give up after coupling.handshake_timeout seconds.
//
// At the end, each program says goodbye: a normal ~World sends a zero-length message to the
// other program (on a duplicate of the intercommunicator) and waits, sleeping, for the other's
// goodbye. A program still waiting for packets when the goodbye arrives (the two programs
// disagree on the number of exchanges) ends the job after a short grace period
// (check_peer), instead of waiting forever.
#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <string>

#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/coupling/side_info.hpp"
#include "coupler_lib/coupling/stall_watch.hpp"
#include "coupler_lib/coupling/wait.hpp"
#include "coupler_lib/errors.hpp"

namespace lbdem {

// What the other program said about itself at the handshake.
struct PeerInfo {
  std::string side;     // "fluid" or "dem"
  std::string program;  // its executable name
  std::string scene;    // the scene file it read
  std::uint64_t scene_hash = 0;
  std::uint32_t protocol = 0;
  int size = 0;  // its number of ranks
};

struct ConnectOptions {
  std::uint32_t protocol = kProtocolVersion;  // announced version (tests announce others)
};

// This program's side of the coupling. Owns the intercommunicator; move-only. Couplers keep
// a pointer to it: construct the World in its final place and keep it alive (and unmoved)
// while they are used.
class World {
 public:
  World() = default;
  World(MPI_Comm side, MPI_Comm inter, PeerInfo peer, WaitMode wait, double stall_timeout = 0);
  World(World&& o) noexcept;
  World& operator=(World&& o) noexcept;
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  ~World();

  MPI_Comm side() const { return side_; }    // the ranks of this program
  MPI_Comm inter() const { return inter_; }  // local group: this program; remote: the other
  int rank() const { return rank_; }
  int size() const { return size_; }
  const PeerInfo& peer() const { return peer_; }
  WaitMode wait() const { return wait_; }
  double stall_timeout() const { return stall_timeout_; }  // coupling.stall_timeout
  // The program's one stall watch: the exchanges and the agreements time their waits on it
  // (bookkeeping of waits, hence usable through a const World).
  StallWatch& stall() const { return stall_; }

  // Called while waiting for packets: throws SideError when the other program said goodbye
  // more than a grace period ago (it finished; what this program waits for will not come).
  void check_peer() const;

 private:
  void close() noexcept;

  MPI_Comm side_ = MPI_COMM_NULL;
  MPI_Comm inter_ = MPI_COMM_NULL;
  MPI_Comm control_ = MPI_COMM_NULL;                // goodbyes travel here
  mutable MPI_Request goodbye_ = MPI_REQUEST_NULL;  // the other program's goodbye
  mutable bool peer_left_ = false;
  mutable std::chrono::steady_clock::time_point peer_left_at_{};
  int rank_ = 0, size_ = 1;
  double stall_timeout_ = 0;
  PeerInfo peer_;
  WaitMode wait_ = WaitMode::backoff;
  mutable StallWatch stall_;
};

// Collective over MPI_COMM_WORLD. Throws JobError when the handshake finds a mismatch,
// SideError when the other program does not show up in time.
World connect(const SideInfo& ctx, const ConnectOptions& options = {});

// "mpirun -np A fluid_app scene.yaml : -np B dem_app scene.yaml" for this scene.
std::string coupled_launch_line(const std::string& scene_file);

}  // namespace lbdem
