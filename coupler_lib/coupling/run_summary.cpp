#include "coupler_lib/coupling/run_summary.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <sstream>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/scene/json_text.hpp"

namespace lbdem {

RankTable gather_per_rank(const std::vector<std::string>& names, const std::vector<double>& mine,
                          MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int n = static_cast<int>(mine.size()), lo = 0, hi = 0;
  MPI_Allreduce(&n, &lo, 1, MPI_INT, MPI_MIN, comm);
  MPI_Allreduce(&n, &hi, 1, MPI_INT, MPI_MAX, comm);
  if (lo != hi)
    throw SideError("run summary: the ranks report " + std::to_string(lo) + " to " +
                    std::to_string(hi) + " counters; every rank must set the same ones");
  std::vector<double> all(rank == 0 ? std::size_t(n) * std::size_t(size) : 0);
  MPI_Gather(mine.data(), n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, 0, comm);
  RankTable t;
  if (rank != 0) return t;
  t.names = names;
  t.per_rank.assign(std::size_t(n), std::vector<double>(std::size_t(size)));
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < n; ++c)
      t.per_rank[std::size_t(c)][std::size_t(r)] =
          all[std::size_t(r) * std::size_t(n) + std::size_t(c)];
  return t;
}

double max_over_mean(const std::vector<double>& v) {
  if (v.empty()) return 1;
  const double mean = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
  return mean > 0 ? *std::max_element(v.begin(), v.end()) / mean : 1;
}

double max_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

std::string run_summary_json(const RunSummary& s) {
  std::ostringstream o;
  o << "{\n";
  o << "  \"program\": " << json_string(s.program) << ",\n";
  o << "  \"side\": " << json_string(s.side) << ",\n";
  o << "  \"version\": " << json_string(s.version) << ",\n";
  o << "  \"scene\": " << json_string(s.scene_file) << ",\n";
  std::ostringstream hex;
  hex << std::hex << s.fingerprint;
  o << "  \"scene_fingerprint\": " << json_string(hex.str()) << ",\n";
  o << "  \"ranks\": {\"fluid\": " << s.fluid_ranks << ", \"dem\": " << s.dem_ranks << "},\n";
  o << "  \"steps\": {\"first\": " << s.first_step << ", \"last\": " << s.last_step
    << ", \"schedule\": " << s.schedule_steps << "},\n";
  o << "  \"dt_s\": " << json_number(s.dt) << ",\n";
  o << "  \"simulated_time_s\": " << json_number(double(s.last_step) * s.dt) << ",\n";
  o << "  \"end\": " << json_string(s.end) << ",\n";
  o << "  \"exit_status\": " << s.exit_status << ",\n";
  o << "  \"last_checkpoint\": " << json_string(s.last_checkpoint) << ",\n";
  o << "  \"wall_s\": " << json_number(s.wall_s) << ",\n";
  o << "  \"before_steps_s\": " << json_number(s.before_steps_s) << ",\n";
  o << "  \"per_step_s\": {";
  for (std::size_t i = 0; i < s.per_step_s.size(); ++i)
    o << (i ? ", " : "") << json_string(s.per_step_s[i].first) << ": "
      << json_number(s.per_step_s[i].second);
  o << "},\n";
  o << "  \"per_step_cpu_s\": {";
  for (std::size_t i = 0; i < s.per_step_cpu_s.size(); ++i)
    o << (i ? ", " : "") << json_string(s.per_step_cpu_s[i].first) << ": "
      << json_number(s.per_step_cpu_s[i].second);
  o << "},\n";
  o << "  \"per_rank\": {";
  for (std::size_t c = 0; c < s.ranks.names.size(); ++c) {
    const auto& v = s.ranks.per_rank[c];
    const double mean =
        std::accumulate(v.begin(), v.end(), 0.0) / double(std::max<std::size_t>(v.size(), 1));
    o << (c ? "," : "") << "\n    " << json_string(s.ranks.names[c])
      << ": {\"values\": " << json_list(v)
      << ", \"min\": " << json_number(*std::min_element(v.begin(), v.end()))
      << ", \"mean\": " << json_number(mean)
      << ", \"max\": " << json_number(*std::max_element(v.begin(), v.end())) << "}";
  }
  o << "\n  },\n";
  double imbalance = 1;
  for (std::size_t c = 0; c < s.ranks.names.size(); ++c)
    if (s.ranks.names[c] == s.imbalance_of) imbalance = max_over_mean(s.ranks.per_rank[c]);
  o << "  \"load_imbalance\": {\"of\": " << json_string(s.imbalance_of)
    << ", \"max_over_mean\": " << json_number(imbalance) << "},\n";
  o << "  \"outputs\": [";
  for (std::size_t i = 0; i < s.outputs.size(); ++i)
    o << (i ? ", " : "") << json_string(s.outputs[i]);
  o << "]\n}\n";
  return o.str();
}

std::string run_summary_path(const Scene& scene, const std::string& side) {
  std::filesystem::path dir(scene.dem     ? scene.dem->output.directory
                            : scene.fluid ? scene.fluid->output.directory
                                          : std::string("."));
  if (dir.is_relative()) dir = std::filesystem::path(scene.file).parent_path() / dir;
  return (dir / (scene.name + "_" + side + "_summary.json")).lexically_normal().string();
}

}  // namespace lbdem
