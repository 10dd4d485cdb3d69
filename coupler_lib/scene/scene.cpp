#include "coupler_lib/scene/scene.hpp"

#include <fstream>
#include <iomanip>
#include <sstream>

#include "coupler_lib/scene/coupled_limits.hpp"
#include "coupler_lib/scene/scene_paths.hpp"
#include "coupler_lib/scene/section_agreement.hpp"

namespace lbdem {

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

Scene parse_scene(Section root, std::uint64_t hash) {
  Scene sc;
  sc.file = root.file();
  sc.hash = hash;
  sc.source = root.source();
  sc.name = root.get<std::string>("name", "scene",
                                  "name used in output file names (letters, digits, - _ .)");
  check_plain_name(root, "name", sc.name);
  sc.log_level = root.choice("log_level", "info", {"trace", "debug", "info", "warn", "error"},
                             "logging level (the command line's --log-level wins)");
  {
    auto t = root.section("time", "simulated time span");
    sc.time.end = t.require<double>("end", "simulated end time in s", Bounds::positive());
    sc.time.progress_interval = t.get<double>(
        "progress_interval", 10.0, "wall seconds between progress lines", Bounds::positive());
    t.finish();
  }
  if (auto f = root.optional_section("fluid", "lattice Boltzmann fluid"))
    sc.fluid = parse_fluid(*f);
  auto dem = root.optional_section("dem", "discrete element bodies (LAMMPS)");
  if (dem) sc.dem = parse_dem(*dem);
  sc.shapes = parse_shapes(root);
  sc.bodies = parse_bodies(root, sc.shapes);
  {
    auto c = root.section_or_defaults("coupling", "fluid-DEM packet exchange");
    sc.coupling = parse_coupling(c);
  }
  root.finish();
  if (!sc.fluid && !sc.dem)
    throw SceneError(sc.file + ": the scene has neither a 'fluid' nor a 'dem' section");
  if (sc.dem) {
    check_sections_agree(sc, *dem);
    resolve_lubrication(sc.dem->lubrication, sc.fluid ? &*sc.fluid : nullptr, sc.file);
  }
  check_coupled_limits(sc);
  return sc;
}

Scene load_scene(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(file + ": cannot open the scene file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_scene(Section::load_file(file), fnv1a(ss.str()));
}

std::string describe_resolved(const Scene& scene) {
  std::ostringstream s;
  for (const auto& k : scene.source->resolved) {
    s << "  " << std::left << std::setw(36) << k.path << " = " << std::setw(14) << k.value
      << (k.defaulted ? " (default)" : "          ") << "  # " << k.doc << "\n";
  }
  return s.str();
}

}  // namespace lbdem
