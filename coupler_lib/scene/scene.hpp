#pragma once
// A scene: the one YAML file both binaries read. Parsing is shared, so both sides reject
// the same mistakes with the same message, and the hash of the file lets the handshake
// check that both sides read the same scene.
#include <cstdint>
#include <optional>
#include <string>

#include "coupler_lib/scene/bodies_section.hpp"
#include "coupler_lib/scene/coupling_section.hpp"
#include "coupler_lib/scene/dem_section.hpp"
#include "coupler_lib/scene/fluid_section.hpp"
#include "coupler_lib/scene/shapes_section.hpp"
#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

struct TimeParams {
  double end = 0;                 // simulated seconds
  double progress_interval = 10;  // wall seconds between progress lines
};

struct Scene {
  std::string file;
  std::uint64_t hash = 0;  // FNV-1a of the file bytes
  std::string name;
  LogLevel log_level = LogLevel::info;
  TimeParams time;
  std::optional<FluidParams> fluid;  // absent: DEM-only scene
  std::optional<DemParams> dem;      // absent: fluid-only scene
  std::vector<ShapeParams> shapes;
  std::vector<BodyParams> bodies;
  CouplingParams coupling;
  std::shared_ptr<SceneSource> source;  // resolved keys, for --check

  bool coupled() const { return fluid && dem && !bodies.empty(); }
};

Scene load_scene(const std::string& file);
Scene parse_scene(Section root, std::uint64_t hash);
std::uint64_t fnv1a(const std::string& bytes);

// Every resolved key with its value, default marker and documentation.
std::string describe_resolved(const Scene& scene);

}  // namespace lbdem
