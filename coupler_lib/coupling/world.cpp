#include "coupler_lib/coupling/world.hpp"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstring>
#include <exception>
#include <utility>

namespace lbdem {

namespace {

constexpr std::uint32_t kHelloMagic = 0x4c42444d;  // "LBDM"
constexpr int kIntercommTag = 4711;
constexpr int kGoodbyeTag = 4712;
// Packets the other program sent before its goodbye may still be on their way.
constexpr std::chrono::seconds kGoodbyeGrace{5};

// The first message between the programs. Plain bytes; the magic and protocol come first so
// a peer with a different layout is still recognised as such.
struct Hello {
  std::uint32_t magic = kHelloMagic;
  std::uint32_t protocol = 0;
  std::uint64_t scene_hash = 0;
  std::int32_t size = 0;
  std::int32_t app = 0;
  char side[16] = {};
  char program[64] = {};
  char scene[512] = {};
};

template <size_t N>
void put(char (&dst)[N], const std::string& s) {
  std::snprintf(dst, N, "%s", s.c_str());
}

Hello hello_of(const SideInfo& ctx, std::uint32_t protocol) {
  Hello h;
  h.protocol = protocol;
  h.scene_hash = ctx.scene_hash;
  h.size = ctx.size;
  h.app = ctx.app;
  put(h.side, ctx.side);
  put(h.program, ctx.program);
  put(h.scene, ctx.scene_file);
  return h;
}

std::string hex(std::uint64_t v) {
  char b[32];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(v));
  return b;
}

// The same text on every rank of both programs: `a` is application 0, `b` application 1.
std::string mismatch(const Hello& a, const Hello& b) {
  const std::string pa = a.program, pb = b.program;
  if (a.magic != kHelloMagic || b.magic != kHelloMagic)
    return "the two programs do not speak the coupling protocol (" + pa + " : " + pb + ")";
  if (a.protocol != b.protocol)
    return "coupling protocol version mismatch: " + pa + " speaks version " +
           std::to_string(a.protocol) + ", " + pb + " speaks version " +
           std::to_string(b.protocol) + "; build both programs from the same source tree";
  const std::string sa = a.side, sb = b.side;
  if (sa == sb || (sa != "fluid" && sa != "dem") || (sb != "fluid" && sb != "dem"))
    return "wrong pair of programs: " + pa + " (" + sa + " side) : " + pb + " (" + sb +
           " side); a coupled scene needs one fluid and one DEM program: " +
           coupled_launch_line(a.scene);
  if (a.scene_hash != b.scene_hash) {
    const std::string fa = a.scene, fb = b.scene;
    return "the two programs read different scenes: " + pa + " read '" + fa + "' (hash " +
           hex(a.scene_hash) + "), " + pb + " read '" + fb + "' (hash " + hex(b.scene_hash) + ")" +
           (fa == fb ? " (same name, different contents)" : "") +
           "; give both programs the same scene file";
  }
  return "";
}

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

PeerInfo peer_of(const Hello& h) {
  return {h.side, h.program, h.scene, h.scene_hash, h.protocol, h.size};
}

}  // namespace

std::string coupled_launch_line(const std::string& scene_file) {
  return "mpirun -np A fluid_app " + scene_file + " : -np B dem_app " + scene_file;
}

World::World(MPI_Comm side, MPI_Comm inter, PeerInfo peer, WaitMode wait, double stall_timeout)
    : side_(side),
      inter_(inter),
      stall_timeout_(stall_timeout),
      peer_(std::move(peer)),
      wait_(wait),
      stall_(stall_timeout, peer_) {
  MPI_Comm_rank(side_, &rank_);
  MPI_Comm_size(side_, &size_);
  MPI_Comm_dup(inter_, &control_);
  // Zero-length, so no buffer has to stay put while the World moves.
  MPI_Irecv(nullptr, 0, MPI_INT, MPI_ANY_SOURCE, kGoodbyeTag, control_, &goodbye_);
}

World::World(World&& o) noexcept {
  *this = std::move(o);
}

World& World::operator=(World&& o) noexcept {
  if (this != &o) {
    close();
    side_ = o.side_;
    inter_ = std::exchange(o.inter_, MPI_COMM_NULL);
    control_ = std::exchange(o.control_, MPI_COMM_NULL);
    goodbye_ = std::exchange(o.goodbye_, MPI_REQUEST_NULL);
    peer_left_ = o.peer_left_;
    peer_left_at_ = o.peer_left_at_;
    rank_ = o.rank_;
    size_ = o.size_;
    peer_ = std::move(o.peer_);
    wait_ = o.wait_;
    stall_timeout_ = o.stall_timeout_;
    stall_ = std::move(o.stall_);
  }
  return *this;
}

World::~World() {
  close();
}

void World::close() noexcept {
  if (inter_ == MPI_COMM_NULL) return;
  // Unwinding an error: the process is about to abort the job, which ends the other program
  // too; waiting for its goodbye here could wait forever.
  if (std::uncaught_exceptions() > 0) return;
  // Remote rank j hears from local rank j % size, so every rank gets exactly one goodbye.
  for (int j = rank_; j < peer_.size; j += size_)
    MPI_Send(nullptr, 0, MPI_INT, j, kGoodbyeTag, control_);
  wait_request(goodbye_, WaitMode::backoff);
  MPI_Comm_free(&control_);
  MPI_Comm_free(&inter_);
}

void World::check_peer() const {
  if (inter_ == MPI_COMM_NULL) return;
  if (!peer_left_) {
    int done = 0;
    MPI_Test(&goodbye_, &done, MPI_STATUS_IGNORE);
    if (!done) return;
    peer_left_ = true;
    peer_left_at_ = std::chrono::steady_clock::now();
  }
  if (std::chrono::steady_clock::now() - peer_left_at_ > kGoodbyeGrace)
    throw SideError(peer_.program + " (the " + peer_.side +
                    " side) finished while this program still waits for its packets: the two "
                    "programs disagree on the number of coupling exchanges");
}

World connect(const SideInfo& ctx, const ConnectOptions& options) {
  const std::string& scene = ctx.scene_file;
  if (ctx.app_count == 1)
    throw JobError(scene + " couples a fluid with bodies, but only " + ctx.program +
                   " was launched; start both programs: " + coupled_launch_line(scene) +
                   " (or run one side alone from a recording with --replay FILE)");
  if (ctx.app_count > 2)
    throw JobError("the launch started " + std::to_string(ctx.app_count) +
                   " programs; a coupled scene needs exactly two: " + coupled_launch_line(scene));

  // Leaders: the lowest world rank of each program. Nonblocking, so a program that never
  // comes to the handshake is noticed instead of waited for forever.
  int mine[2] = {INT_MAX, INT_MAX}, lead[2] = {0, 0};
  mine[ctx.app] = ctx.world_rank;
  MPI_Request req;
  MPI_Iallreduce(mine, lead, 2, MPI_INT, MPI_MIN, MPI_COMM_WORLD, &req);
  const double timeout = ctx.coupling.handshake_timeout;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::microseconds(static_cast<long long>(timeout * 1e6));
  if (!wait_request_until(req, deadline))
    throw SideError("the other program did not reach the coupling handshake within " +
                    seconds(timeout) +
                    " s (coupling.handshake_timeout): it failed or finished before coupling");

  MPI_Comm inter = MPI_COMM_NULL;
  MPI_Intercomm_create(ctx.side_comm, 0, MPI_COMM_WORLD, lead[1 - ctx.app], kIntercommTag, &inter);

  // Rank 0 of each program swaps hellos, then shares the peer's with its own ranks.
  Hello own = hello_of(ctx, options.protocol), peer;
  if (ctx.rank == 0) {
    MPI_Request r[2];
    MPI_Irecv(&peer, sizeof(Hello), MPI_BYTE, 0, kIntercommTag, inter, &r[0]);
    MPI_Isend(&own, sizeof(Hello), MPI_BYTE, 0, kIntercommTag, inter, &r[1]);
    for (auto& q : r) wait_request(q, WaitMode::backoff);
  }
  MPI_Bcast(&peer, sizeof(Hello), MPI_BYTE, 0, ctx.side_comm);
  peer.program[sizeof peer.program - 1] = peer.side[sizeof peer.side - 1] =
      peer.scene[sizeof peer.scene - 1] = '\0';

  const std::string problem = ctx.app == 0 ? mismatch(own, peer) : mismatch(peer, own);
  if (!problem.empty()) {
    MPI_Comm_free(&inter);
    throw JobError(problem);
  }
  return World(ctx.side_comm, inter, peer_of(peer), ctx.coupling.wait, ctx.coupling.stall_timeout);
}

}  // namespace lbdem
