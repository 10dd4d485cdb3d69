#pragma once
// The stall watchdog of one side of a coupled run. A rank of the other program that stops
// (SIGSTOP, a hung node, a deadlock) sends nothing, and a program that only waits for its
// packets would wait forever. While waiting for the other program, the transports ask
// check() between two tests of the request; once one wait lasts longer than the limit, check()
// throws SideError naming the silent side, the last exchange this side completed and the last
// checkpoint, and run_app ends the whole job (MPI_Abort also ends the stopped process).
//
// The limit is coupling.stall_timeout when given; else it is generous and grows with the run:
// the larger of kAutomaticFloor and kAutomaticFactor x the longest wall time seen so far between
// two completed exchanges (a run that slows down gradually is not a stall).
#include <chrono>
#include <cstdint>
#include <string>

#include "coupler_lib/coupling/world.hpp"

namespace lbdem {

class StallWatch {
 public:
  static constexpr double kAutomaticFloor = 600;  // wall s
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
  Clock::time_point wait_start_{}, last_end_{};
  double slowest_gap_s_ = 0;
};

}  // namespace lbdem
