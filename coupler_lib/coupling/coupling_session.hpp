#pragma once
// The coupled clock: one object per program that owns the schedule, the step labels, the
// agreement of both programs on stop requests and instabilities, the checkpoint protocol and
// the end-of-run report. Each program's loop holds only its physics:
//
//   CouplingSession session(ctx, scene, schedule, &world);   // or nullptr: alone (replay)
//   session.on_checkpoint([&](const std::string& prefix, const CheckpointHeader& h) {
//     ... write this program's half of the checkpoint ...
//   });
//   while (session.ongoing()) {
//     const std::int64_t step = session.next_step();
//     ... fluid: stream-collide, loads, exchange; DEM: substeps, exchange ...
//     session.advance(flags, [&] { ... take this step's body states ... });
//   }
//   return session.finish(coupler.times());
//
// advance() completes step next_step(). At the agreement steps (agreement_at: every
// fluid.stability.interval steps, every checkpoint step, the last step) both programs combine
// their flags (kFluidUnstable, kBodiesUnstable, and kStopRequested from SIGTERM / SIGINT) in
// one reduction over both programs. An agreed instability ends the run before `accept` runs,
// so a program never embeds states the other found non-finite; otherwise `accept` runs, then
// at a checkpoint step or on an agreed stop request the checkpoint writer writes this half,
// both programs wait for each other's half, and older checkpoints are pruned
// (docs/reliability.md, "Checkpoint and restart").
//
// With coupling.overlap the fluid waits for the DEM's states at every agreement step
// (StateFeed's sync), so both programs hold the same step when they agree and checkpoint.
// Alone (a replay) there is no agreement: a local instability ends the local run at once.
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "coupler_lib/coupling/checkpoint_files.hpp"
#include "coupler_lib/coupling/coupling_times.hpp"
#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/coupling/side_info.hpp"
#include "coupler_lib/coupling/stop_request.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

// Why a coupled run ended.
enum class SessionEnd {
  running,         // not ended yet
  completed,       // reached time.end
  stop_requested,  // a stop signal, agreed by both programs: checkpoint written
  unstable,        // a stability watch of either program, agreed by both (or alone)
};

class CouplingSession {
 public:
  using CheckpointWriter =
      std::function<void(const std::string& prefix, const CheckpointHeader& header)>;

  // `world`: the live connection (must outlive the session), nullptr when this program runs
  // alone from a recording. With agreement (live) the stop handlers are installed
  // and the checkpoint folder is created. Collective over this program's ranks.
  CouplingSession(const SideInfo& side, const Scene& scene, const Schedule& schedule,
                  const World* world);
  CouplingSession(const CouplingSession&) = delete;
  CouplingSession& operator=(const CouplingSession&) = delete;

  // A restart: the run continues after `step`, the checkpoint `prefix` is the last good one.
  void resume(const std::string& prefix, std::int64_t step);
  void on_checkpoint(CheckpointWriter writer) { writer_ = std::move(writer); }

  bool ongoing() const { return end_ == SessionEnd::running && step_ < schedule_.steps; }
  std::int64_t step() const { return step_; }  // completed outer steps
  std::int64_t next_step() const { return step_ + 1; }
  double time_of(std::int64_t step) const { return double(step) * schedule_.dt; }
  const Schedule& schedule() const { return schedule_; }
  int fluid_ranks() const { return fluid_ranks_; }  // 0 for the absent side in a replay
  int dem_ranks() const { return dem_ranks_; }

  // This program's checkpoint header for `step` (a restart checks its half against header(0)).
  CheckpointHeader header(std::int64_t step) const;

  // Whether both programs agree and checkpoint (live).
  bool agrees() const { return agrees_; }
  // Whether `step` is an agreement step. The same steps alone (a replay): an overlapped fluid
  // waits for the states there, live or replayed, so both see the same sequence of states.
  bool agreement_at(std::int64_t step) const;
  bool output_at(std::int64_t step) const { return schedule_.output_at(step); }
  bool checkpoint_at(std::int64_t step) const { return agrees_ && schedule_.checkpoint_at(step); }

  // Completes next_step(). `flags`: kFluidUnstable / kBodiesUnstable found by this program
  // (kept until the next agreement step). `accept` runs when the step's states are sound.
  // Collective over both programs at agreement steps.
  void advance(int flags, const std::function<void()>& accept = {});

  // Adds the wall time of `f` to the named part of this program's step (end-of-run split), and
  // the CPU time of this thread in it (what the part costs on a core of its own: on shared
  // cores the wall time also holds the time other processes ran).
  template <class F>
  decltype(auto) timed(const char* part, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    struct Add {
      CouplingSession* s;
      const char* part;
      std::chrono::steady_clock::time_point start;
      double cpu_start;
      ~Add() {
        s->add_time(part,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                    thread_cpu_seconds() - cpu_start);
      }
    } add{this, part, start, thread_cpu_seconds()};
    return f();
  }
  void add_time(const std::string& part, double seconds, double cpu_seconds = 0);
  // A note printed after the part's time in the split, e.g. "2 substeps".
  void describe(const std::string& part, const std::string& note);

  // This rank's value of a work counter (cells, bodies, atoms, ...), reported per rank at the
  // end. Every rank of the program sets the same names in the same order.
  void count(const std::string& name, double value);
  // A file this run wrote, listed in the run summary (rank 0's list is written).
  void output(const std::string& path) { outputs_.push_back(path); }

  SessionEnd end() const { return end_; }
  int agreed_flags() const { return agreed_; }  // the flags of the agreement that ended the run
  const std::string& last_checkpoint() const { return checkpoint_; }

  // Marks the start of the steps: what the coupler did so far (the first exchange, which
  // waits for the other program's set-up) is reported as the wait before the first step and
  // left out of the time per step. Call it right before the step loop.
  void steps_begin(const CouplingTimes& coupler_so_far) { before_steps_ = coupler_so_far; }

  // "time per coupled step (<side> rank 0): <part> <s> s (<note>), ..., exchange <s> s, idle
  // (waiting for <peer>) <s> s", per step run in this process (tools/coupled_bench.py reads it).
  std::string step_split(const CouplingTimes& coupler) const;

  // Collective over this program's ranks. Rank 0 logs how the run ended (with the restart
  // command where one applies), the time per step split into the parts timed() measured plus
  // the coupler's exchange and idle time, and the per-rank work: every counter and the max RSS
  // as min / mean / max over the ranks, and the load imbalance (max / mean of the busy time,
  // the timed parts, per step). It writes the run summary (run_summary.hpp) next to the body
  // trace. `coupler`: the coupler's times of the whole run (steps_begin's part is taken off).
  // Returns the exit status: 0, or kExitUnstable.
  int finish(const CouplingTimes& coupler);

 private:
  void write_checkpoint(std::int64_t step);
  void report_work(const CouplingTimes& coupler);  // collective: log lines and the summary

  const SideInfo& side_;
  const Scene& scene_;
  Schedule schedule_;
  const World* world_;
  bool agrees_ = false;
  int fluid_ranks_ = 0, dem_ranks_ = 0;
  std::int64_t step_ = 0;
  std::int64_t first_ = 0;  // the step the run started from
  int pending_ = 0;         // this program's flags since the last agreement
  int agreed_ = 0;
  SessionEnd end_ = SessionEnd::running;
  CheckpointWriter writer_;
  std::string checkpoint_;  // the last one written or restarted from
  struct Counter {
    std::string name;
    double value = 0;
  };
  std::vector<Counter> counters_;
  std::vector<std::string> outputs_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  CouplingTimes before_steps_;  // the coupler's times up to the first step (steps_begin)
  struct Part {
    std::string name, note;
    double seconds = 0;
    double cpu_seconds = 0;
  };
  Part& part(const std::string& name);
  std::vector<Part> parts_;  // in the order first timed
};

}  // namespace lbdem
