#pragma once
// The command line both binaries share:
//   APP [--check [--json]] [--replay FILE] [--restart CHECKPOINT] [--log-level L] scene.yaml
//   APP --schema
#include <optional>
#include <string>
#include <vector>

namespace lbdem {

struct CommandLine {
  std::string scene;
  bool check = false;
  bool json = false;  // --check prints the resolved scene as JSON on stdout (implies check)
  bool help = false;
  bool version = false;
  bool schema = false;    // print the scene schema (coupler_lib/scene/schema.hpp) and stop
  std::string replay;     // recording to replay this side from
  std::string restart;    // checkpoint (either half, its prefix or its folder) to continue from
  std::string log_level;  // overrides the scene's log_level
};

// Throws std::invalid_argument with a user-facing message on bad arguments.
CommandLine parse_command_line(const std::vector<std::string>& args);
std::string usage(const std::string& app, const std::string& what);

}  // namespace lbdem
