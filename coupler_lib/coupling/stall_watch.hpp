#pragma once
// The stall watchdog of one side of a coupled run. A rank of the other program that stops
// (SIGSTOP, a hung node, a deadlock) sends nothing, and a program that only waits for its
// packets would wait forever. While waiting for the other program (its packets, or the
// agreement of both programs at a stability or checkpoint step), the transports and the
// agreement ask check() between two tests of the request; once one wait lasts longer than the
// limit, check() throws SideError naming the silent side, what this side waits for, the last
// exchange it completed and the last checkpoint, and run_app ends the whole job (MPI_Abort also
// ends the stopped process). One watch per program (World::stall), so the packets and the
// agreements share the measured step time.
//
// The limit is coupling.stall_timeout when given; else it is automatic:
//   * the waits of the first two exchanges hold the other program's set-up and first step
//     (lattice, porosity field, LAMMPS; they grow with the scene): kSetUpLimit;
//   * from then on the larger of kAutomaticFloor and kAutomaticFactor x the longest wall time
//     seen so far between two completed waits (a run that slows down gradually, or whose fluid
//     runs its stability check, a pass over the lattice, at an agreement step, is not a stall),
//     so that a stopped rank of a fast run ends the job about a minute after it stopped;
//   * the waits that hold a long pause the schedule announces (PauseSteps: a checkpoint or a
//     field output, whose writing grows with the lattice, not with the step time) get at least
//     kSetUpLimit, and their gaps are not counted as steps.
#include <chrono>
#include <cstdint>
#include <string>

#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

struct PeerInfo;

// The exchange steps at which either program may pause for long by schedule: after writing a
// checkpoint (both programs) or the fluid's fields. The waits labelled with such a step or the
// one after it hold the pause (the writes come before the step's last wait or the next one).
struct PauseSteps {
  std::int64_t checkpoint_every = 0;  // 0: none
  std::int64_t fields_every = 0;      // 0: none
  bool at(std::int64_t step) const;
  bool held_by(std::int64_t wait_step) const { return at(wait_step) || at(wait_step - 1); }
};
PauseSteps pause_steps(const Scene& scene, const Schedule& schedule);

class StallWatch {
 public:
  static constexpr double kSetUpLimit = 600;     // wall s, the first kSetUpWaits waits
  static constexpr int kSetUpWaits = 4;          // two per exchange: states and loads
  static constexpr double kAutomaticFloor = 60;  // wall s
  static constexpr double kAutomaticFactor = 50;

  StallWatch() = default;
  // `timeout_s` > 0: a fixed limit in wall seconds; 0: automatic (see above).
  StallWatch(double timeout_s, const PeerInfo& peer);

  void expect_pauses(const PauseSteps& pauses) { pauses_ = pauses; }

  // What a wait is for. The set-up allowance counts packet waits only, so an agreement early
  // in the run does not use it up.
  enum class Wait { packets, agreement };
  // A wait for the other program's part of exchange `step`.
  void begin(std::int64_t step, Wait kind = Wait::packets);
  void check() const;  // throws SideError when the current wait is too long
  void end();          // that wait completed

  double limit_s() const;  // the limit that applies to the current wait

 private:
  using Clock = std::chrono::steady_clock;
  double timeout_s_ = 0;
  std::string peer_;
  PauseSteps pauses_;
  std::int64_t step_ = 0;
  Wait kind_ = Wait::packets;
  std::int64_t last_completed_ = -1;  // -1: none yet
  int completed_ = 0;                 // packet waits completed
  Clock::time_point wait_start_{}, last_end_{};
  double slowest_gap_s_ = 0;
};

// The limit a coupled run of `scene` works with, in words, for --check: the fixed
// coupling.stall_timeout or the automatic rule above; with checkpoints, the size of the fluid's.
std::string describe_stall_limit(const Scene& scene);

}  // namespace lbdem
