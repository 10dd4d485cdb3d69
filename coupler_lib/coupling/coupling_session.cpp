#include "coupler_lib/coupling/coupling_session.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>

#include "coupler_lib/coupling/run_summary.hpp"
#include "coupler_lib/errors.hpp"
#include "coupler_lib/output/atomic_file.hpp"
#include "coupler_lib/scene/scene_fingerprint.hpp"

namespace lbdem {

namespace {

constexpr int kUnstable = kFluidUnstable | kBodiesUnstable;

// This program's own instability flag.
int own_flag(const SideInfo& side) {
  return side.side == "fluid" ? kFluidUnstable : kBodiesUnstable;
}

std::string side_label(const SideInfo& side) {
  return side.side == "dem" ? "DEM" : side.side;
}

const char* end_word(SessionEnd e) {
  switch (e) {
    case SessionEnd::running:
      return "running";
    case SessionEnd::completed:
      return "completed";
    case SessionEnd::stop_requested:
      return "stop_requested";
    case SessionEnd::unstable:
      return "unstable";
  }
  return "?";
}

}  // namespace

CouplingSession::CouplingSession(const SideInfo& side, const Scene& scene, const Schedule& schedule,
                                 const World* world)
    : side_(side), scene_(scene), schedule_(schedule), world_(world) {
  // Live, both programs agree; with coupling.overlap the fluid waits for the states of every
  // agreement step (StateFeed's sync), so both hold the same step when they agree and write.
  agrees_ = world_ != nullptr;
  const int peer = world_ ? world_->peer().size : 0;
  fluid_ranks_ = side.side == "fluid" ? side.size : peer;
  dem_ranks_ = side.side == "fluid" ? peer : side.size;
  if (!agrees_) return;
  // Both programs know the schedule: the waits around the other's checkpoint and field writes
  // get the pause allowance of the stall watch.
  world_->stall().expect_pauses(pause_steps(scene, schedule));
  install_stop_handlers();
  if (side.rank == 0) std::filesystem::create_directories(checkpoint_directory(scene));
}

void CouplingSession::resume(const std::string& prefix, std::int64_t step) {
  remember_checkpoint(prefix);
  checkpoint_ = prefix;
  step_ = first_ = step;
}

CheckpointHeader CouplingSession::header(std::int64_t step) const {
  return make_checkpoint_header(scene_, side_.side, step, time_of(step), fluid_ranks_, dem_ranks_);
}

bool CouplingSession::agreement_at(std::int64_t step) const {
  return lbdem::agreement_at(scene_, schedule_, step);
}

void CouplingSession::advance(int flags, const std::function<void()>& accept) {
  const std::int64_t step = next_step();
  pending_ |= flags & kUnstable;
  if (!agrees_) {
    // Alone (a replay): nobody to agree with, a local instability ends the run now.
    step_ = step;
    if (pending_) {
      agreed_ = pending_;
      end_ = SessionEnd::unstable;
      return;
    }
    if (accept) accept();
    if (step_ == schedule_.steps) end_ = SessionEnd::completed;
    return;
  }
  int agreed = 0;
  if (agreement_at(step)) {
    agreed = agree_flags(pending_ | (stop_signal() != 0 ? kStopRequested : 0), *world_, step);
    pending_ = 0;
  }
  step_ = step;
  if (agreed & kUnstable) {
    agreed_ = agreed;
    end_ = SessionEnd::unstable;
    return;
  }
  if (accept) accept();
  const bool stop = (agreed & kStopRequested) != 0;
  if (stop || schedule_.checkpoint_at(step)) write_checkpoint(step);
  if (stop) {
    agreed_ = agreed;
    end_ = SessionEnd::stop_requested;
  } else if (step_ == schedule_.steps) {
    end_ = SessionEnd::completed;
  }
}

void CouplingSession::write_checkpoint(std::int64_t step) {
  if (!writer_)
    throw SideError(side_.program + ": a checkpoint is due at step " + std::to_string(step) +
                    " but this program registered no checkpoint writer");
  const std::string prefix = checkpoint_prefix(scene_, step);
  writer_(prefix, header(step));
  // Older checkpoints go only once both halves of this one exist.
  wait_for_both(*world_, step);
  remember_checkpoint(prefix);
  checkpoint_ = prefix;
  if (side_.rank == 0) prune_checkpoints(scene_, side_.side, scene_.coupling.checkpoint_keep);
}

CouplingSession::Part& CouplingSession::part(const std::string& name) {
  auto it =
      std::find_if(parts_.begin(), parts_.end(), [&](const Part& p) { return p.name == name; });
  if (it != parts_.end()) return *it;
  parts_.push_back(Part{name, {}, 0, 0});
  return parts_.back();
}

void CouplingSession::add_time(const std::string& name, double seconds, double cpu_seconds) {
  Part& p = part(name);
  p.seconds += seconds;
  p.cpu_seconds += cpu_seconds;
}

void CouplingSession::count(const std::string& name, double value) {
  for (Counter& c : counters_)
    if (c.name == name) {
      c.value = value;
      return;
    }
  counters_.push_back(Counter{name, value});
}

void CouplingSession::describe(const std::string& name, const std::string& note) {
  part(name).note = note;
}

std::string CouplingSession::step_split(const CouplingTimes& coupler) const {
  const double n = double(std::max<std::int64_t>(step_ - first_, 1));
  const std::string peer = world_ ? world_->peer().program : std::string("the recording");
  std::string line = "time per coupled step (" + side_label(side_) + " rank 0): ";
  for (const Part& p : parts_) {
    line += fmt::format("{} {:.3e} s", p.name, p.seconds / n);
    if (!p.note.empty()) line += " (" + p.note + ")";
    line += ", ";
  }
  return line + fmt::format("exchange {:.3e} s, idle (waiting for {}) {:.3e} s",
                            coupler.exchange_s() / n, peer, coupler.idle_s / n);
}

int CouplingSession::finish(const CouplingTimes& coupler) {
  if (end_ == SessionEnd::running && step_ >= schedule_.steps) end_ = SessionEnd::completed;
  const std::string peer = world_ ? world_->peer().program : std::string("the recording");
  const bool lead = side_.rank == 0;
  const auto& log = side_.log;
  const std::string& last = remembered_checkpoint();
  if (lead && end_ == SessionEnd::unstable) {
    // Both programs stop here; the one that found the problem printed the diagnosis.
    if (!(agreed_ & own_flag(side_)))
      log->error("stopped at step {}: {} found the {} unstable (its diagnosis above)", step_, peer,
                 side_.side == "fluid" ? "bodies" : "fluid");
    log->error("last good checkpoint: {}",
               last.empty() ? std::string("none (set coupling.checkpoint_interval)")
                            : last + "; continue after changing the scene with: " +
                                  restart_command(scene_, last, fluid_ranks_, dem_ranks_));
  } else if (lead && end_ == SessionEnd::stop_requested) {
    log->info("stopped on request (signal {}) at step {} (t = {:.6e} s); checkpoint: {}",
              stop_signal() != 0 ? std::to_string(stop_signal()) : "on another rank", step_,
              time_of(step_), checkpoint_);
    log->info("continue with: {}", restart_command(scene_, checkpoint_, fluid_ranks_, dem_ranks_));
  } else if (lead) {
    log->info("coupled {} run finished after {} steps", side_label(side_), step_);
  }
  const CouplingTimes steps = since(coupler, before_steps_);
  if (lead && step_ > first_) {
    log->info(
        "coupler before the first step: {:.3f} s, of which {:.3f} s waiting for {} (its "
        "set-up; not in the time per step)",
        before_steps_.total_s, before_steps_.idle_s, peer);
    log->info("{}", step_split(steps));
  }
  report_work(steps);
  return end_ == SessionEnd::unstable ? kExitUnstable : 0;
}

void CouplingSession::report_work(const CouplingTimes& coupler) {
  const double n = double(std::max<std::int64_t>(step_ - first_, 1));
  double busy = 0, busy_cpu = 0;
  for (const Part& p : parts_) {
    busy += p.seconds;
    busy_cpu += p.cpu_seconds;
  }
  std::vector<std::string> names{"busy_s_per_step",        "busy_cpu_s_per_step",
                                 "coupler_cpu_s_per_step", "max_rss_mib",
                                 "coupler_bytes_per_step", "coupler_messages_per_step"};
  std::vector<double> mine{busy / n,
                           busy_cpu / n,
                           coupler.cpu_s / n,
                           max_rss_mib(),
                           double(coupler.bytes) / n,
                           double(coupler.messages) / n};
  for (const Counter& c : counters_) {
    names.push_back(c.name);
    mine.push_back(c.value);
  }
  RankTable table = gather_per_rank(names, mine, side_.side_comm);
  if (side_.rank != 0) return;
  const std::string label = side_label(side_);
  for (std::size_t c = 0; c < table.names.size(); ++c) {
    const auto& v = table.per_rank[c];
    double sum = 0;
    for (double x : v) sum += x;
    side_.log->info("per-rank work ({}, {} ranks): {} min {:.6g} mean {:.6g} max {:.6g}", label,
                    v.size(), table.names[c], *std::min_element(v.begin(), v.end()),
                    sum / double(v.size()), *std::max_element(v.begin(), v.end()));
  }
  side_.log->info("load imbalance ({}): {:.3f} (max / mean of the busy time per step)", label,
                  max_over_mean(table.per_rank[0]));
  for (std::size_t c = 0; c < table.names.size(); ++c)
    if (table.names[c] == "weighted_work")
      side_.log->info("load imbalance ({}): {:.3f} (max / mean of the weighted work)", label,
                      max_over_mean(table.per_rank[c]));
  RunSummary s;
  s.program = side_.program;
  s.side = side_.side;
  s.scene_file = scene_.file;
  s.version = LBDEM_VERSION;
  s.fingerprint = scene_fingerprint(scene_);
  s.fluid_ranks = fluid_ranks_;
  s.dem_ranks = dem_ranks_;
  s.first_step = first_;
  s.last_step = step_;
  s.schedule_steps = schedule_.steps;
  s.dt = schedule_.dt;
  s.end = end_word(end_);
  s.exit_status = end_ == SessionEnd::unstable ? kExitUnstable : 0;
  s.last_checkpoint = remembered_checkpoint();
  s.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  s.before_steps_s = before_steps_.total_s;
  for (const Part& p : parts_) {
    s.per_step_s.emplace_back(p.name, p.seconds / n);
    s.per_step_cpu_s.emplace_back(p.name, p.cpu_seconds / n);
  }
  s.per_step_cpu_s.emplace_back("exchange", coupler.cpu_s / n);
  s.per_step_s.emplace_back("exchange", coupler.exchange_s() / n);
  s.per_step_s.emplace_back("idle", coupler.idle_s / n);
  s.ranks = std::move(table);
  s.imbalance_of = "busy_s_per_step";
  s.outputs = outputs_;
  const std::string path = run_summary_path(scene_, side_.side);
  if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty())
    std::filesystem::create_directories(dir);
  write_file_atomically(path, run_summary_json(s));
  side_.log->info("run summary: {}", path);
}

}  // namespace lbdem
