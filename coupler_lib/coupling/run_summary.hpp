#pragma once
// The run summary: one JSON file per program at the end of a coupled run, and fluid_app's at
// the end of a fluid-only run, for scripts (tools/lbdem/rundir.py opens it) and for comparing
// runs without parsing log lines.
//
//   <dem.output.directory>/<scene name>_<side>_summary.json
//   <fluid.output.directory>/<scene name>_fluid_summary.json   (no bodies, fluid.output given)
//
// It holds the scene (file, fingerprint), the program and version, the rank counts of both
// programs, the steps run (first, last, of the schedule), how the run ended and its exit
// status, the last checkpoint, the wall time, the coupler's time before the first step (the
// other program's set-up) and the time per step split into parts (wall and
// CPU seconds of the timed parts), and per
// rank every work counter with its min / mean / max and the load imbalance (max / mean of the
// busy time per step). Keys are documented in docs/user-guide.md ("Run summary").
#include <mpi.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

// Counters per rank, gathered on rank 0 of a program: per_rank[c][r] is counter c of rank r.
struct RankTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> per_rank;
};

// Collective over `comm`: every rank gives the same names with its own values; rank 0 gets
// the table (other ranks an empty one). Throws SideError when the ranks disagree on the count.
RankTable gather_per_rank(const std::vector<std::string>& names, const std::vector<double>& mine,
                          MPI_Comm comm);

double max_over_mean(const std::vector<double>& v);  // 1 for an empty or all-zero row
double max_rss_mib();                                // this process's peak resident memory, MiB

struct RunSummary {
  std::string program, side, scene_file, version, end, last_checkpoint;
  std::uint64_t fingerprint = 0;
  int fluid_ranks = 0, dem_ranks = 0, exit_status = 0;
  std::int64_t first_step = 0, last_step = 0, schedule_steps = 0;
  double dt = 0, wall_s = 0;
  double before_steps_s = 0;  // in the coupler before the first step (the peer's set-up)
  std::vector<std::pair<std::string, double>> per_step_s;      // part -> seconds per step (rank 0)
  std::vector<std::pair<std::string, double>> per_step_cpu_s;  // its CPU seconds (rank 0)
  RankTable ranks;
  std::string imbalance_of;  // the counter whose max / mean is the load imbalance
  std::vector<std::string> outputs;
};

std::string run_summary_json(const RunSummary& s);
std::string run_summary_path(const Scene& scene, const std::string& side);

}  // namespace lbdem
