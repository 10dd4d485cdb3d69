#include "coupler_lib/app/run_app.hpp"

#include <cstdio>
#include <iostream>

namespace lbdem {

namespace {

// Which application of an MPMD launch this process belongs to (0 when launched alone),
// and how many applications there are.
void appnum(int& mine, int& count) {
  int flag = 0;
  int* value = nullptr;
  MPI_Comm_get_attr(MPI_COMM_WORLD, MPI_APPNUM, &value, &flag);
  mine = flag && value ? *value : 0;
  MPI_Allreduce(&mine, &count, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  count += 1;
}

[[noreturn]] void abort_all(const std::string& who, const std::string& what) {
  std::fprintf(stderr, "[%s] error: %s\n", who.c_str(), what.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();
}

}  // namespace

int run_app(int argc, char** argv, const AppInfo& info,
            const std::function<void(AppContext&)>& check,
            const std::function<int(AppContext&)>& run) {
  MPI_Init(&argc, &argv);
  AppContext ctx;
  ctx.info = info;
  MPI_Comm_rank(MPI_COMM_WORLD, &ctx.world_rank);
  int app = 0;
  appnum(app, ctx.app_count);
  MPI_Comm_split(MPI_COMM_WORLD, app, ctx.world_rank, &ctx.side_comm);
  MPI_Comm_rank(ctx.side_comm, &ctx.rank);
  MPI_Comm_size(ctx.side_comm, &ctx.size);
  const std::string who = info.side + " " + std::to_string(ctx.rank);

  // Errors every rank sees alike: report once, finalize collectively, exit 1.
  auto collective_failure = [&](const std::string& msg, bool show_usage) {
    if (ctx.world_rank == 0) {
      std::fprintf(stderr, "%s: error: %s\n", info.program.c_str(), msg.c_str());
      if (show_usage) std::fprintf(stderr, "%s", usage(info.program, info.description).c_str());
      std::fflush(stderr);
    }
    MPI_Comm_free(&ctx.side_comm);
    MPI_Finalize();
    return 1;
  };

  try {
    std::vector<std::string> args(argv + 1, argv + argc);
    ctx.cli = parse_command_line(args);
  } catch (const std::invalid_argument& e) {
    return collective_failure(e.what(), true);
  }
  if (ctx.cli.help || ctx.cli.version) {
    if (ctx.world_rank == 0) {
      if (ctx.cli.help)
        std::cout << usage(info.program, info.description);
      else
        std::cout << info.program << " " << LBDEM_VERSION << "\n";
    }
    MPI_Comm_free(&ctx.side_comm);
    MPI_Finalize();
    return 0;
  }
  try {
    ctx.scene = load_scene(ctx.cli.scene);
  } catch (const SceneError& e) {
    return collective_failure(e.what(), false);
  }
  const std::string level = ctx.cli.log_level.empty() ? ctx.scene.log_level : ctx.cli.log_level;
  ctx.log = make_logger(info.side, ctx.rank, level);

  int rc = 0;
  try {
    if (ctx.cli.check) {
      check(ctx);
    } else {
      rc = run(ctx);
    }
  } catch (const SceneError& e) {
    // Side-specific validation: detected by all ranks of this side.
    if (ctx.rank == 0) abort_all(who, e.what());
    // Let rank 0 print before the job is torn down.
    MPI_Barrier(ctx.side_comm);
    MPI_Abort(MPI_COMM_WORLD, 1);
  } catch (const std::exception& e) {
    abort_all(who, e.what());
  }
  ctx.log->flush();
  MPI_Comm_free(&ctx.side_comm);
  MPI_Finalize();
  return rc;
}

}  // namespace lbdem
