#include "dem_app/coupling/body_trace.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <vector>

#include "coupler_lib/output/series_resume.hpp"
#include "dem_app/output/output_chunks.hpp"

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
  const std::vector<BodyState> my_states = sorted_by_id(states);
  const std::vector<BodyLoad> my_loads = sorted_by_id(loads);
  const std::int64_t end = std::max(id_end(my_states, comm_), id_end(my_loads, comm_));
  for (std::int64_t lo = 0; lo < end; lo += kOutputChunk) {
    const std::int64_t hi = std::min(end, lo + kOutputChunk);
    const std::vector<BodyState> chunk_states = gather_id_range(my_states, lo, hi, comm_);
    const std::vector<BodyLoad> chunk_loads = gather_id_range(my_loads, lo, hi, comm_);
    if (rank_ != 0) continue;
    std::map<std::int64_t, const BodyLoad*> by_id;  // the last one in rank order
    for (const auto& l : chunk_loads) by_id[l.id] = &l;
    for (const auto& s : chunk_states) {
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
  }
  if (rank_ == 0) out_.flush();
}

}  // namespace lbdem
