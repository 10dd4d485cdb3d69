#include "coupler_lib/app/command_line.hpp"

#include "coupler_lib/scene/choices.hpp"

#include <stdexcept>

namespace lbdem {

CommandLine parse_command_line(const std::vector<std::string>& args) {
  CommandLine c;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* opt) {
      if (i + 1 >= args.size()) throw std::invalid_argument(std::string(opt) + " needs a value");
      return args[++i];
    };
    if (a == "--help" || a == "-h")
      c.help = true;
    else if (a == "--version")
      c.version = true;
    else if (a == "--check")
      c.check = true;
    else if (a == "--schema")
      c.schema = true;
    else if (a == "--json")
      c.json = c.check = true;
    else if (a == "--replay")
      c.replay = value("--replay");
    else if (a == "--restart")
      c.restart = value("--restart");
    else if (a == "--log-level")
      c.log_level = value("--log-level");
    else if (!a.empty() && a[0] == '-')
      throw std::invalid_argument("unknown option '" + a + "'");
    else if (c.scene.empty())
      c.scene = a;
    else
      throw std::invalid_argument("more than one scene file given ('" + c.scene + "', '" + a +
                                  "')");
  }
  if (!c.help && !c.version && !c.schema && c.scene.empty())
    throw std::invalid_argument("no scene file given");
  if (c.schema && (c.check || !c.scene.empty() || !c.replay.empty() || !c.restart.empty()))
    throw std::invalid_argument("--schema takes no scene and no other option");
  if (!c.replay.empty() && !c.restart.empty())
    throw std::invalid_argument("--replay and --restart cannot be combined");
  if (!c.log_level.empty() && !find_word(kLogLevelWords, c.log_level))
    throw std::invalid_argument("--log-level expects trace, debug, info, warn or error");
  return c;
}

std::string usage(const std::string& app, const std::string& what) {
  return "usage: " + app + " [options] scene.yaml\n       " + app + " --schema\n" + what +
         "\n\noptions:\n"
         "  --check           validate the scene, print the derived parameters, do not run\n"
         "  --json            with --check: print the resolved scene as JSON on stdout\n"
         "                    (every key with its default, derived numbers, bodies)\n"
         "  --schema          print the schema of every scene key as JSON (the same from both\n"
         "                    programs; docs/scene-reference.md is generated from it)\n"
         "  --replay FILE     run this side alone, fed from a recording (HDF5)\n"
         "  --restart CKPT    continue a coupled run from a checkpoint (a .fluid.h5 or .dem.h5\n"
         "                    file, their common prefix, or the checkpoint folder: the newest)\n"
         "  --log-level L     trace | debug | info | warn | error (overrides the scene)\n"
         "  --version         print the version\n"
         "  --help            this text\n"
         "\ncoupled launch:  mpirun -np A fluid_app scene.yaml : -np B dem_app scene.yaml\n";
}

}  // namespace lbdem
