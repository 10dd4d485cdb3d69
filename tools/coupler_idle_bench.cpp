// coupler_idle_bench: how much CPU a coupled program burns while it waits for the other.
//
//   mpirun -np 2 coupler_idle_bench [--seconds S] [--share-core] [--bodies N]
//   mpirun -np 1 coupler_idle_bench : -np 1 coupler_idle_bench      (MPMD, same result)
//
// The ranks form two groups joined by an intercommunicator, as fluid_app and dem_app are.
// The first group computes for S wall seconds and then joins a barrier over the
// intercommunicator; the second group waits in that barrier, once with the coupler's
// back-off wait (wait.hpp) and once with a plain blocking MPI_Wait. The table gives the
// waiting side's CPU time (getrusage: user + system, all threads) against wall time, and
// the computing rank's own CPU/wall (its share of a core: on a busy machine the waiter can
// only take a similar share) and its work rate relative to the back-off run. With --share-core
// every rank is pinned to core 0, so the waiter competes with the computing rank for one core, as
// when both programs share a node's cores. Last, the cost of the exchange itself: round trips of N
// states (DEM -> fluid) and N loads (fluid -> DEM) with no computation in between, and what the
// exchange costs a side that arrives while the other waits asleep (an overlapped coupled step).
#include <mpi.h>
#include <sched.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "coupler_lib/coupling/exchange.hpp"
#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/coupling/wait.hpp"

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Stand-in for a fluid or DEM step: floating-point work for `seconds` of wall time.
// Returns the number of work units done.
double compute_for(double seconds) {
  const double end = now() + seconds;
  volatile double acc = 1.0;
  double units = 0;
  while (now() < end) {
    for (int i = 0; i < 20000; ++i) acc = acc * 1.0000001 + 1e-9;
    units += 1;
  }
  return units;
}

struct Result {
  double wall = 0, cpu = 0, work = 0;
};

Result run_mode(MPI_Comm inter, bool computing, double seconds, lbdem::WaitMode mode) {
  Result r;
  MPI_Barrier(MPI_COMM_WORLD);
  const double t0 = now(), c0 = cpu_seconds();
  if (computing) r.work = compute_for(seconds);
  MPI_Request req;
  MPI_Ibarrier(inter, &req);
  lbdem::wait_request(req, computing ? lbdem::WaitMode::backoff : mode);
  r.wall = now() - t0;
  r.cpu = cpu_seconds() - c0;
  return r;
}

// One coupling round trip without computation: the waiting group (as the DEM side) sends
// `bodies` states spread over the computing group's ranks, which answer with one load each.
// Returns seconds per round trip.
double round_trip(MPI_Comm inter, bool fluid, long bodies, int rounds, lbdem::WaitMode mode) {
  const int peers = lbdem::remote_size(inter);
  int me = 0, mine = 0;
  MPI_Comm_rank(inter, &me);
  MPI_Comm_size(inter, &mine);
  std::vector<std::vector<lbdem::BodyState>> states(static_cast<size_t>(peers));
  if (!fluid)
    for (long id = me; id < bodies; id += mine) {
      lbdem::BodyState b;
      b.id = id;
      states[static_cast<size_t>(id % peers)].push_back(b);
    }
  lbdem::PacketSender sender(inter);
  MPI_Barrier(MPI_COMM_WORLD);
  const double t0 = now();
  for (int r = 0; r < rounds; ++r) {
    if (fluid) {
      const auto got = lbdem::receive_packets<lbdem::BodyState>(inter, mode);
      std::vector<std::vector<lbdem::BodyLoad>> loads(static_cast<size_t>(peers));
      for (size_t p = 0; p < got.size(); ++p)
        for (const auto& b : got[p]) {
          lbdem::BodyLoad l;
          l.id = b.id;
          loads[p].push_back(l);
        }
      sender.send(loads, mode);
    } else {
      sender.send(states, mode);
      lbdem::receive_packets<lbdem::BodyLoad>(inter, mode);
    }
  }
  sender.complete(mode);
  return (now() - t0) / rounds;
}

// The overlapped step's pattern: the waiting group (as the DEM) has its states ready and waits
// in the exchange, asleep after its back-off spin; the computing group (as the fluid) arrives
// `late` seconds later, receives the states and answers with the loads. Returns the computing
// group's seconds inside the two exchanges per step: what the fluid pays beyond its own work.
double late_arrival(MPI_Comm inter, bool fluid, long bodies, int rounds, double late,
                    lbdem::WaitMode mode) {
  const int peers = lbdem::remote_size(inter);
  int me = 0, mine = 0;
  MPI_Comm_rank(inter, &me);
  MPI_Comm_size(inter, &mine);
  std::vector<std::vector<lbdem::BodyState>> states(static_cast<size_t>(peers));
  std::vector<std::vector<lbdem::BodyLoad>> loads(static_cast<size_t>(peers));
  for (long id = me; id < bodies; id += mine) {
    const auto p = static_cast<size_t>(id % peers);
    if (fluid) {
      loads[p].emplace_back();
      loads[p].back().id = id;
    } else {
      states[p].emplace_back();
      states[p].back().id = id;
    }
  }
  lbdem::PacketSender sender(inter);
  double inside = 0;
  for (int r = 0; r < rounds; ++r) {
    MPI_Barrier(MPI_COMM_WORLD);
    if (fluid) {
      compute_for(late);
      const double t0 = now();
      lbdem::receive_packets<lbdem::BodyState>(inter, mode);
      sender.send(loads, mode);
      inside += now() - t0;
    } else {
      sender.send(states, mode);
      lbdem::receive_packets<lbdem::BodyLoad>(inter, mode);
    }
  }
  sender.complete(mode);
  MPI_Allreduce(MPI_IN_PLACE, &inside, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return inside / rounds;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  double seconds = 3;
  bool share_core = false;
  long bodies = 10000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc)
      seconds = std::stod(argv[++i]);
    else if (!std::strcmp(argv[i], "--share-core"))
      share_core = true;
    else if (!std::strcmp(argv[i], "--bodies") && i + 1 < argc)
      bodies = std::stol(argv[++i]);
  }
  int rank = 0, size = 1, flag = 0, app = 0, apps = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int* appnum = nullptr;
  MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_APPNUM, &appnum, &flag);
  app = flag && appnum ? *appnum : 0;
  MPI_Allreduce(&app, &apps, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (size < 2) {
    if (rank == 0) std::fprintf(stderr, "coupler_idle_bench needs at least 2 ranks\n");
    MPI_Finalize();
    return 1;
  }
  // Group 0 computes, group 1 waits: by application in an MPMD launch, else by rank halves.
  const int group = apps >= 1 ? (app == 0 ? 0 : 1) : (rank < size / 2 ? 0 : 1);
  if (share_core) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(0, &set);
    sched_setaffinity(0, sizeof set, &set);
  }
  MPI_Comm side, inter;
  MPI_Comm_split(MPI_COMM_WORLD, group, rank, &side);
  int first_of_other = 0, mine = group == 1 ? rank : size;
  MPI_Allreduce(&mine, &first_of_other, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  MPI_Intercomm_create(side, 0, MPI_COMM_WORLD, group == 0 ? first_of_other : 0, 17, &inter);

  const char* names[2] = {"backoff", "blocking"};
  const lbdem::WaitMode modes[2] = {lbdem::WaitMode::backoff, lbdem::WaitMode::blocking};
  Result res[2];
  for (int m = 0; m < 2; ++m) res[m] = run_mode(inter, group == 0, seconds, modes[m]);

  // Rank 0 computes; the first waiting rank reports the waiting side.
  double wait_stats[4] = {res[0].wall, res[0].cpu, res[1].wall, res[1].cpu};
  double work[2] = {res[0].work, res[1].work};
  if (group == 1 && rank == first_of_other && rank != 0)
    MPI_Send(wait_stats, 4, MPI_DOUBLE, 0, 1, MPI_COMM_WORLD);
  if (rank == 0) {
    MPI_Recv(wait_stats, 4, MPI_DOUBLE, first_of_other, 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::printf(
        "coupler_idle_bench: %d computing rank(s), %d waiting rank(s), %.1f s of compute%s\n",
        first_of_other, size - first_of_other, seconds, share_core ? ", all ranks on core 0" : "");
    std::printf("%-9s %10s %10s %10s %18s %20s\n", "wait", "wall s", "CPU s", "CPU/wall",
                "computer CPU/wall", "compute work (rel.)");
    for (int m = 0; m < 2; ++m)
      std::printf("%-9s %10.3f %10.3f %9.1f%% %17.1f%% %20.3f\n", names[m], wait_stats[2 * m],
                  wait_stats[2 * m + 1], 100.0 * wait_stats[2 * m + 1] / wait_stats[2 * m],
                  100.0 * res[m].cpu / res[m].wall, work[m] / work[0]);
  }
  // Coupling overhead on its own: round trips with no computation on either side.
  for (int m = 0; m < 2; ++m) {
    const double t = round_trip(inter, group == 0, bodies, 50, modes[m]);
    if (rank == 0)
      std::printf("%s exchange of %ld states + %ld loads: %.3f ms per round trip\n", names[m],
                  bodies, bodies, 1e3 * t);
  }
  // The overlapped coupled step: the study's 64 cubes, the peer waiting 10 ms.
  for (int m = 0; m < 2; ++m) {
    const double t = late_arrival(inter, group == 0, 64, 50, 0.010, modes[m]);
    if (rank == 0)
      std::printf(
          "%s wait, peer waiting 10 ms: 64 states + 64 loads cost the late side %.3f ms "
          "per step\n",
          names[m], 1e3 * t);
  }
  MPI_Comm_free(&inter);
  MPI_Comm_free(&side);
  MPI_Finalize();
  return 0;
}
