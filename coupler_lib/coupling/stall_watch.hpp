#pragma once
// The stall watchdog of one side of a coupled run. A rank of the other program that stops
// (SIGSTOP, a hung node, a deadlock) sends nothing, and a program that only waits for its
// packets would wait forever. While waiting for the other program, the transports ask
// check() between two tests of the request; once one wait lasts longer than the limit, check()
// throws SideError naming the silent side, the last exchange this side completed and the last
// checkpoint, and run_app ends the whole job (MPI_Abort also ends the stopped process).
//
// The limit is coupling.stall_timeout when given; else it is automatic. The waits of the first
// two exchanges hold the other program's set-up and first step (lattice, porosity field, LAMMPS;
// they grow with the scene): they get kSetUpLimit. From then on the limit is the larger of
// kAutomaticFloor and kAutomaticFactor x the longest wall time seen so far between two completed
// waits after the set-up (a run that slows down gradually, or writes a large checkpoint once, is
// not a stall), so that a stopped rank of a fast run ends the job about a minute after it stopped.
#include <chrono>
#include <cstdint>
#include <string>

#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

class StallWatch {
 public:
  static constexpr double kSetUpLimit = 600;     // wall s, the first kSetUpWaits waits
  static constexpr int kSetUpWaits = 4;          // two per exchange: states and loads
  static constexpr double kAutomaticFloor = 60;  // wall s
  static constexpr double kAutomaticFactor = 50;

  // `timeout_s` > 0: a fixed limit in wall seconds; 0: automatic (see above).
  StallWatch(double timeout_s, const PeerInfo& peer);

  void begin(std::int64_t step);  // a wait for the other program's part of exchange `step`
  void check() const;             // throws SideError when the current wait is too long
  void end();                     // that wait completed

  double limit_s() const;  // the limit that applies to the current wait

 private:
  using Clock = std::chrono::steady_clock;
  double timeout_s_;
  std::string peer_;
  std::int64_t step_ = 0;
  std::int64_t last_completed_ = -1;  // -1: none yet
  int completed_ = 0;                 // waits completed
  Clock::time_point wait_start_{}, last_end_{};
  double slowest_gap_s_ = 0;
};

// The limit a coupled run of `scene` works with, in words, for --check: the fixed
// coupling.stall_timeout or the automatic rule above; with checkpoints, the size of the fluid's
// and how long it may take to write before the automatic limit could mistake it for a stall.
std::string describe_stall_limit(const Scene& scene);

}  // namespace lbdem
