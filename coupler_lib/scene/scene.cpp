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

namespace {

const MappingSchema& time_schema() {
  static const MappingSchema m{
      "time",
      "simulated time span",
      {key::number("end", "simulated end time in s").required().within(Bounds::positive()).in("s"),
       key::number("progress_interval", "wall seconds between progress lines")
           .or_default(10.0)
           .within(Bounds::positive())
           .in("s")}};
  return m;
}

}  // namespace

const MappingSchema& scene_schema() {
  static const MappingSchema m{
      "",
      "the scene file: one YAML mapping of sections, read by both programs",
      {key::text("name", "name used in output file names (letters, digits, - _ .)")
           .or_default("scene"),
       key::choice("log_level", words_of(kLogLevelWords),
                   "logging level (the command line's --log-level wins)")
           .or_default("info"),
       key::section("time", time_schema(), "simulated time span").required(),
       key::section("fluid", fluid_schema(), "lattice Boltzmann fluid")
           .absent_means("no fluid: a DEM-only scene"),
       key::section("dem", dem_schema(), "discrete element bodies (LAMMPS)")
           .absent_means("no DEM: a fluid-only scene"),
       key::list("shapes", shape_schema(), "catalogue of body shapes").absent_means("no shapes"),
       key::list("bodies", body_schema(), "bodies: single bodies, generators and files")
           .absent_means("no bodies"),
       key::section("coupling", coupling_schema(), "fluid-DEM packet exchange")
           .absent_means("all defaults")},
      {},
      {},
      {{"fluid", "dem"}}};
  return m;
}

Scene parse_scene(Section root, std::uint64_t hash) {
  Scene sc;
  sc.file = root.file();
  sc.hash = hash;
  sc.source = root.source();
  sc.name = root.get<std::string>("name");
  check_plain_name(root, "name", sc.name);
  sc.log_level = value_of(kLogLevelWords, root.choice("log_level"));
  {
    auto t = root.section("time");
    sc.time.end = t.require<double>("end");
    sc.time.progress_interval = t.get<double>("progress_interval");
    t.finish();
  }
  if (auto f = root.optional_section("fluid")) sc.fluid = parse_fluid(*f);
  auto dem = root.optional_section("dem");
  if (dem) sc.dem = parse_dem(*dem);
  sc.shapes = parse_shapes(root);
  sc.bodies = parse_bodies(root, sc.shapes);
  {
    auto c = root.section_or_defaults("coupling");
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
