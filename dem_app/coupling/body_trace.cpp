#include "dem_app/coupling/body_trace.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <vector>

namespace lbdem {

namespace {

// Raw-byte gather of trivially copyable packets to rank 0.
template <class P>
std::vector<P> gather(std::span<const P> mine, MPI_Comm comm, int rank) {
  int size = 0;
  MPI_Comm_size(comm, &size);
  const int bytes = static_cast<int>(mine.size() * sizeof(P));
  std::vector<int> counts(static_cast<size_t>(size)), displs(static_cast<size_t>(size));
  MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  int total = 0;
  for (int r = 0; r < size; ++r) {
    displs[size_t(r)] = total;
    total += counts[size_t(r)];
  }
  std::vector<P> all(rank == 0 ? size_t(total) / sizeof(P) : 0);
  MPI_Gatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, 0,
              comm);
  return all;
}

}  // namespace

BodyTrace::BodyTrace(const std::string& path, MPI_Comm comm) : path_(path), comm_(comm) {
  MPI_Comm_rank(comm, &rank_);
  if (rank_ != 0) return;
  out_.open(path);
  if (!out_) throw std::runtime_error(path + ": cannot write the body trace");
  out_ << "time,id,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz,fx,fy,fz,tx,ty,tz\n";
  out_.precision(17);  // round-trip digits: the invariance and replay checks compare at round-off
}

void BodyTrace::write(double time, std::span<const BodyState> states,
                      std::span<const BodyLoad> loads) {
  std::vector<BodyState> all_states = gather(states, comm_, rank_);
  std::vector<BodyLoad> all_loads = gather(loads, comm_, rank_);
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
