#include "dem_app/coupling/body_trace.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <vector>

#include "coupler_lib/output/gather.hpp"
#include "coupler_lib/output/series_resume.hpp"

namespace lbdem {

BodyTrace::BodyTrace(const std::string& path, MPI_Comm comm, long long resume_bytes)
    : path_(path), comm_(comm) {
  MPI_Comm_rank(comm, &rank_);
  if (rank_ != 0) return;
  out_.precision(17);  // round-trip digits: the invariance and replay checks compare at round-off
  if (resume_bytes >= 0) {
    cut_series_to(path, resume_bytes);
    out_.open(path, std::ios::app);
    if (!out_) throw std::runtime_error(path + ": cannot append to the body trace");
    return;
  }
  out_.open(path);
  if (!out_) throw std::runtime_error(path + ": cannot write the body trace");
  out_ << "time,id,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz,fx,fy,fz,tx,ty,tz\n";
}

long long BodyTrace::flushed_bytes() {
  if (rank_ != 0) return 0;
  out_.flush();
  return static_cast<long long>(out_.tellp());
}

void BodyTrace::write(double time, std::span<const BodyState> states,
                      std::span<const BodyLoad> loads) {
  std::vector<BodyState> all_states = gather_to_root(states, comm_);
  std::vector<BodyLoad> all_loads = gather_to_root(loads, comm_);
  if (rank_ != 0) return;
  std::map<std::int64_t, const BodyLoad*> by_id;
  for (const auto& l : all_loads) by_id[l.id] = &l;
  std::sort(all_states.begin(), all_states.end(),
            [](const BodyState& a, const BodyState& b) { return a.id < b.id; });
  for (const auto& s : all_states) {
    const BodyLoad zero{};
    const BodyLoad& l = by_id.count(s.id) ? *by_id[s.id] : zero;
    out_ << time << ',' << s.id;
    for (double v : s.x) out_ << ',' << v;
    for (double v : s.v) out_ << ',' << v;
    for (double v : s.w) out_ << ',' << v;
    for (double v : s.q) out_ << ',' << v;
    for (double v : l.f) out_ << ',' << v;
    for (double v : l.t) out_ << ',' << v;
    out_ << '\n';
  }
  out_.flush();
}

}  // namespace lbdem
