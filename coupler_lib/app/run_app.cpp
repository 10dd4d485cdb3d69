#include "coupler_lib/app/run_app.hpp"

#include <unistd.h>

#include <atomic>
#include <climits>
#include <cstdio>
#include <iostream>

#include "coupler_lib/app/scene_json.hpp"
#include "coupler_lib/coupling/checkpoint_files.hpp"
#include "coupler_lib/coupling/stall_watch.hpp"
#include "coupler_lib/scene/scene_checks.hpp"

namespace lbdem {

namespace {

// The context of the program whose `run` (or `check`) is executing, null otherwise. This is
// process-wide state by necessity: it is read by the MPI_Finalize interposer below, which a
// library calls without any context.
std::atomic<const AppContext*> running_app{nullptr};

// Sets running_app for the lifetime of a callback.
class RunningApp {
 public:
  explicit RunningApp(const AppContext& ctx) { running_app.store(&ctx); }
  ~RunningApp() { running_app.store(nullptr); }
  RunningApp(const RunningApp&) = delete;
  RunningApp& operator=(const RunningApp&) = delete;
};

// Which application of an MPMD launch this process belongs to (0 when launched alone),
// and how many applications there are. mpirun's MPMD syntax numbers the applications
// (MPI_APPNUM); a launcher that starts several programs as one application (Slurm's
// `srun --multi-prog`, docs/user-guide.md "Clusters") leaves every rank at 0, and then the
// program's side tells them apart: the fluid is application 0, the DEM application 1.
void appnum(const std::string& side, int& mine, int& count) {
  int flag = 0;
  int* value = nullptr;
  MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_APPNUM, &value, &flag);
  mine = flag && value ? *value : 0;
  int highest = 0;
  MPI_Allreduce(&mine, &highest, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  const int by_side = side == "dem" ? 1 : 0;
  int sides[2] = {by_side, -by_side}, range[2] = {0, 0};  // max side index, -min side index
  MPI_Allreduce(sides, range, 2, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  const bool two_sides = range[0] == 1 && range[1] == 0;
  if (highest == 0 && two_sides) {
    mine = by_side;
    highest = 1;
  }
  count = highest + 1;
}

[[noreturn]] void abort_all(const std::string& who, const std::string& what) {
  std::fprintf(stderr, "[%s] error: %s\n", who.c_str(), what.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();
}

// What start-up decided on one rank; the job goes on only if every rank says `run`.
enum class Start { run = 0, stop = 1, fail = 2 };

struct StartOutcome {
  Start start = Start::run;
  std::string error;
  bool show_usage = false;
};

// Physical memory of all the nodes this job runs on (one contribution per node): a lattice
// split over many nodes may need more than one node has. Collective over MPI_COMM_WORLD.
double job_memory_bytes() {
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int node_rank = 0;
  MPI_Comm_rank(node, &node_rank);
  MPI_Comm_free(&node);
  const double mine = node_rank == 0 ? physical_memory_bytes() : 0;
  double total = 0;
  MPI_Allreduce(&mine, &total, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return total;
}

StartOutcome start_up(AppContext& ctx, int argc, char** argv, double memory_bytes) {
  StartOutcome out;
  try {
    std::vector<std::string> args(argv + 1, argv + argc);
    ctx.cli = parse_command_line(args);
  } catch (const std::invalid_argument& e) {
    return {Start::fail, e.what(), true};
  }
  if (ctx.cli.help || ctx.cli.version || ctx.cli.schema) return {Start::stop, "", false};
  try {
    ctx.scene = load_scene(ctx.cli.scene);
    ctx.scene_file = ctx.cli.scene;
    ctx.scene_hash = ctx.scene.hash;
    ctx.coupling = ctx.scene.coupling;
    check_whole_scene(ctx.scene, memory_bytes);
    if (!ctx.cli.restart.empty()) check_restart(ctx.cli.restart, ctx.scene, ctx.side, ctx.size);
  } catch (const std::exception& e) {
    return {Start::fail, e.what(), false};
  }
  if (!ctx.scene.coupled() && ctx.app_count > 1)
    return {Start::fail,
            ctx.cli.scene + ": the scene is not coupled (coupling needs 'fluid', 'dem' and " +
                "'bodies'), but the launch started " + std::to_string(ctx.app_count) +
                " programs; run the one program it needs alone, e.g. mpirun -np N " +
                (ctx.scene.fluid ? "fluid_app " : "dem_app ") + ctx.cli.scene,
            false};
  return out;
}

}  // namespace

int run_app(int argc, char** argv, const AppInfo& info,
            const std::function<void(AppContext&)>& check,
            const std::function<int(AppContext&)>& run) {
  MPI_Init(&argc, &argv);
  AppContext ctx;
  ctx.info = info;
  ctx.side = info.side;
  ctx.program = info.program;
  MPI_Comm_rank(MPI_COMM_WORLD, &ctx.world_rank);
  appnum(info.side, ctx.app, ctx.app_count);
  MPI_Comm_split(MPI_COMM_WORLD, ctx.app, ctx.world_rank, &ctx.side_comm);
  MPI_Comm_rank(ctx.side_comm, &ctx.rank);
  MPI_Comm_size(ctx.side_comm, &ctx.size);
  const std::string who = info.side + " " + std::to_string(ctx.rank);

  auto finish = [&](int rc) {
    MPI_Comm_free(&ctx.side_comm);
    MPI_Finalize();
    return rc;
  };

  // Both binaries agree on the outcome of start-up, so a bad command line or scene on one
  // side cannot leave the other side waiting at the handshake.
  const StartOutcome outcome = start_up(ctx, argc, argv, job_memory_bytes());
  int mine = static_cast<int>(outcome.start), worst = 0;
  MPI_Allreduce(&mine, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (worst == static_cast<int>(Start::fail)) {
    int me = outcome.start == Start::fail ? ctx.world_rank : INT_MAX, first = 0;
    MPI_Allreduce(&me, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (ctx.world_rank == first) {
      std::fprintf(stderr, "%s: error: %s\n", info.program.c_str(), outcome.error.c_str());
      if (outcome.show_usage)
        std::fprintf(stderr, "%s", usage(info.program, info.description).c_str());
      std::fflush(stderr);
    }
    return finish(1);
  }
  if (worst == static_cast<int>(Start::stop)) {
    if (ctx.rank == 0 && ctx.cli.help) std::cout << usage(info.program, info.description);
    if (ctx.rank == 0 && ctx.cli.version) std::cout << info.program << " " << LBDEM_VERSION << "\n";
    // The schema is of the scene file, which both programs read: the same text from either.
    if (ctx.rank == 0 && ctx.cli.schema) std::cout << scene_schema_json() << std::flush;
    return finish(0);
  }
  // --json keeps stderr to warnings, so a tool reads stdout and shows stderr only on failure.
  const std::string level = !ctx.cli.log_level.empty() ? ctx.cli.log_level
                            : ctx.cli.json
                                ? std::string("warn")
                                : std::string(word_of(kLogLevelWords, ctx.scene.log_level));
  ctx.log = make_logger(info.side, ctx.rank, level);

  int rc = 0;
  try {
    const RunningApp guard(ctx);
    if (ctx.cli.check) {
      check(ctx);
      if (ctx.scene.coupled() && ctx.rank == 0)
        ctx.log->info("coupling: {}", describe_stall_limit(ctx.scene));
      if (ctx.cli.json && ctx.rank == 0) std::cout << scene_json(ctx.scene) << std::flush;
    } else {
      rc = run(ctx);
    }
  } catch (const JobError& e) {
    // Every rank of both binaries threw the same: print once, end together.
    if (ctx.world_rank == 0) {
      std::fprintf(stderr, "%s: error: %s\n", info.program.c_str(), e.what());
      std::fflush(stderr);
    }
    return finish(1);
  } catch (const SideError& e) {
    if (ctx.rank == 0) abort_all(who, e.what());
    // Let rank 0 print before the job is torn down.
    MPI_Barrier(ctx.side_comm);
    MPI_Abort(MPI_COMM_WORLD, 1);
  } catch (const SceneError& e) {
    // Side-specific validation: detected by all ranks of this side. Under --check this program
    // runs alone and no rank waits for another: end cleanly, without MPI_Abort's noise.
    if (ctx.cli.check && ctx.app_count == 1) {
      if (ctx.rank == 0) {
        std::fprintf(stderr, "%s: error: %s\n", info.program.c_str(), e.what());
        std::fflush(stderr);
      }
      return finish(1);
    }
    if (ctx.rank == 0) abort_all(who, e.what());
    MPI_Barrier(ctx.side_comm);
    MPI_Abort(MPI_COMM_WORLD, 1);
  } catch (const std::exception& e) {
    abort_all(who, e.what());
  }
  ctx.log->flush();
  return finish(rc);
}

}  // namespace lbdem

// A library that meets an error it cannot throw may call MPI_Finalize and exit: LAMMPS built
// without exceptions does so after every ERROR (Error::all). MPI_Finalize then waits for the
// other program, which waits for this one's packets: the job would hang. While a run is in
// progress a call to MPI_Finalize therefore aborts the whole job instead (PMPI interposition:
// this definition takes the place of the MPI library's, which stays reachable as
// PMPI_Finalize). Outside a run it finalizes as usual.
extern "C" int MPI_Finalize() {
  if (const lbdem::AppContext* ctx = lbdem::running_app.load()) {
    // Every rank of a library's collective error path comes here; rank 0 speaks for them.
    if (ctx->rank != 0) sleep(2);
    std::fprintf(stderr,
                 "[%s %d] error: MPI_Finalize was called in the middle of the run (LAMMPS "
                 "does this after an ERROR: see its message above or in its log file); "
                 "ending the job\n",
                 ctx->info.side.c_str(), ctx->rank);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  return PMPI_Finalize();
}
