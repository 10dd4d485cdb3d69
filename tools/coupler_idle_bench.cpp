// coupler_idle_bench: how much CPU a coupled program burns while it waits for the other.
//
//   mpirun -np 2 coupler_idle_bench [--seconds S] [--share-core]
//   mpirun -np 1 coupler_idle_bench : -np 1 coupler_idle_bench      (MPMD, same result)
//
// The ranks form two groups joined by an intercommunicator, as fluid_app and dem_app are.
// The first group computes for S wall seconds and then joins a barrier over the
// intercommunicator; the second group waits in that barrier, once with the coupler's
// back-off wait (wait.hpp) and once with a plain blocking MPI_Wait. The table gives the
// waiting side's CPU time (getrusage: user + system, all threads) against wall time, and
// the computing side's work rate relative to the back-off run. With --share-core every rank
// is pinned to core 0, so the waiter competes with the computing rank for one core, as when
// both programs share a node's cores.
#include <mpi.h>
#include <sched.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "coupler_lib/comm/wait.hpp"

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

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  double seconds = 3;
  bool share_core = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc)
      seconds = std::stod(argv[++i]);
    else if (!std::strcmp(argv[i], "--share-core"))
      share_core = true;
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
    std::printf("%-9s %12s %12s %10s %22s\n", "wait", "wall s", "CPU s", "CPU/wall",
                "compute work (rel.)");
    for (int m = 0; m < 2; ++m)
      std::printf("%-9s %12.3f %12.3f %9.1f%% %22.3f\n", names[m], wait_stats[2 * m],
                  wait_stats[2 * m + 1], 100.0 * wait_stats[2 * m + 1] / wait_stats[2 * m],
                  work[m] / work[0]);
  }
  MPI_Comm_free(&inter);
  MPI_Comm_free(&side);
  MPI_Finalize();
  return 0;
}
