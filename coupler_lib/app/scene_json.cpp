#include "coupler_lib/app/scene_json.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/scene/dem_time_step.hpp"
#include "coupler_lib/scene/json_text.hpp"
#include "coupler_lib/scene/scene_checks.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"

namespace lbdem {

namespace {

// A JSON value under construction: a leaf (its text), an object (members in insertion order) or
// an array.
struct Node {
  enum class Kind { unset, leaf, object, array } kind = Kind::unset;
  std::string text;
  std::vector<std::pair<std::string, Node>> members;
  std::vector<Node> items;

  Node& member(const std::string& name) {
    become(Kind::object, name);
    for (auto& m : members)
      if (m.first == name) return m.second;
    members.emplace_back(name, Node{});
    return members.back().second;
  }
  Node& item(size_t i) {
    become(Kind::array, "a list");
    if (items.size() <= i) items.resize(i + 1);
    return items[i];
  }
  void set(const std::string& json) {
    become(Kind::leaf, "value");
    text = json;
  }
  void become(Kind k, const std::string& what) {
    // A key recorded both as a value and as a section is a bug of the schema, not of the scene.
    if (kind != Kind::unset && kind != k)
      throw std::logic_error("resolved scene: '" + what + "' is both a value and a section");
    kind = k;
  }
};

// Places a resolved key such as "shapes[0].clump.file" in the tree.
void insert(Node& root, const std::string& path, const std::string& json) {
  Node* at = &root;
  size_t b = 0;
  while (b <= path.size()) {
    size_t e = path.find('.', b);
    if (e == std::string::npos) e = path.size();
    std::string part = path.substr(b, e - b);
    std::vector<size_t> index;
    while (!part.empty() && part.back() == ']') {
      const size_t open = part.rfind('[');
      index.insert(index.begin(), std::stoul(part.substr(open + 1, part.size() - open - 2)));
      part.resize(open);
    }
    at = &at->member(part);
    for (size_t i : index) at = &at->item(i);
    b = e + 1;
  }
  at->set(json);
}

// Objects one member per line; arrays of values, and anything below `compact_depth`, on one line.
void write(const Node& n, std::string& out, int depth, int compact_depth) {
  const bool compact = depth >= compact_depth;
  const std::string pad(2 * static_cast<size_t>(depth + 1), ' ');
  const std::string close_pad(2 * static_cast<size_t>(depth), ' ');
  switch (n.kind) {
    case Node::Kind::unset:
      out += "null";
      return;
    case Node::Kind::leaf:
      out += n.text;
      return;
    case Node::Kind::object:
      out += "{";
      for (size_t i = 0; i < n.members.size(); ++i) {
        out += (i ? "," : "");
        out += compact ? (i ? " " : "") : "\n" + pad;
        out += json_string(n.members[i].first) + ": ";
        write(n.members[i].second, out, depth + 1, compact_depth);
      }
      out += compact || n.members.empty() ? "}" : "\n" + close_pad + "}";
      return;
    case Node::Kind::array: {
      bool values = true;
      for (const auto& e : n.items) values = values && e.kind == Node::Kind::leaf;
      const bool inline_items = compact || values;
      out += "[";
      for (size_t i = 0; i < n.items.size(); ++i) {
        out += (i ? "," : "");
        out += inline_items ? (i ? " " : "") : "\n" + pad;
        write(n.items[i], out, depth + 1, inline_items ? depth : depth + 1);
      }
      out += inline_items || n.items.empty() ? "]" : "\n" + close_pad + "]";
      return;
    }
  }
}

std::string json_int(long long v) {
  return std::to_string(v);
}

void fluid_derived(Node& d, const FluidParams& f, bool bodies) {
  const UnitConverter& u = f.units;
  d.member("dx").set(json_number(u.dx));
  d.member("dt").set(json_number(u.dt));
  d.member("tau").set(json_number(u.tau));
  d.member("nu").set(json_number(u.nu));
  d.member("nu_lattice").set(json_number(u.nu_lattice()));
  d.member("rho").set(json_number(u.rho));
  // Whole numbers: json_number writes them without a fraction ("39").
  d.member("cells").set(
      json_list(std::array<double, 3>{double(f.cells[0]), double(f.cells[1]), double(f.cells[2])}));
  d.member("cell_count").set(json_number(double(f.cells[0]) * f.cells[1] * f.cells[2]));
  d.member("velocity_per_lattice_unit").set(json_number(u.velocity()));
  d.member("acceleration_per_lattice_unit").set(json_number(u.acceleration()));
  d.member("force_per_lattice_unit").set(json_number(u.force()));
  d.member("pressure_per_lattice_unit").set(json_number(u.pressure()));
  const bool flow = u.char_velocity > 0;
  d.member("expected_mach").set(flow ? json_number(u.expected_mach()) : "null");
  d.member("expected_reynolds").set(flow ? json_number(u.expected_reynolds()) : "null");
  d.member("control_every_steps").set(f.control.enabled ? json_int(f.control.every) : "null");
  d.member("memory_bytes").set(json_number(fluid_memory_bytes(f, bodies)));
}

void dem_derived(Node& d, const Scene& scene, const std::vector<Shape>& shapes, double dt_dem) {
  const DemParams& p = *scene.dem;
  const auto box = dem_box(scene);
  d.member("box_lo").set(box ? json_list(box->lo) : "null");
  d.member("box_hi").set(box ? json_list(box->hi) : "null");
  d.member("rayleigh_time").set(json_number(smallest_rayleigh_time(p, shapes, scene.bodies)));
  d.member("dt").set(json_number(dt_dem));
  const auto& l = p.lubrication;
  d.member("lubrication_cutoff").set(l.enabled ? json_number(l.cutoff) : "null");
  d.member("lubrication_viscosity").set(l.enabled ? json_number(l.viscosity) : "null");
}

void schedule_derived(Node& d, const Schedule& s, double end) {
  d.member("end").set(json_number(end));
  d.member("dt").set(json_number(s.dt));
  d.member("dt_dem").set(json_number(s.dt_dem));
  d.member("dem_substeps").set(json_int(s.dem_substeps));
  d.member("steps").set(json_int(s.steps));
  d.member("exchange_interval_steps").set(json_int(s.exchange_interval));
  d.member("output_interval_steps").set(json_int(s.output_interval));
  d.member("checkpoint_interval_steps").set(json_int(s.checkpoint_interval));
}

void shape_entry(Node& n, const ShapeParams& p, const Shape& sh) {
  n.member("name").set(json_string(p.name));
  n.member("kind").set(json_string(std::string(word_of(kShapeKindWords, p.kind))));
  n.member("size").set(json_number(p.size));
  n.member("volume").set(json_number(sh.mass.volume));
  n.member("equivalent_diameter")
      .set(json_number(std::cbrt(6.0 * sh.mass.volume / std::numbers::pi)));
  n.member("bounding_radius").set(json_number(sh.bounding_radius));
  n.member("voxel_size").set(json_number(sh.voxel_spacing));
  const auto& m = sh.mass.principal_moments;
  n.member("principal_moments_per_density").set(json_list(std::array<double, 3>{m[0], m[1], m[2]}));
  n.member("clump_spheres").set(json_int(static_cast<long long>(sh.clump.size())));
  n.member("clump_smallest_radius")
      .set(sh.clump.size() ? json_number(smallest_sphere_radius(sh)) : "null");
  n.member("clump_source").set(json_string(sh.clump_source));
}

void body_entry(Node& n, size_t i, const BodyParams& b, const Scene& scene,
                const std::vector<Shape>& shapes) {
  const auto k = static_cast<size_t>(b.shape);
  n.member("index").set(json_int(static_cast<long long>(i)));
  n.member("shape").set(json_string(scene.shapes[k].name));
  n.member("position").set(json_list(b.position));
  n.member("orientation").set(json_list(b.orientation));
  n.member("velocity").set(json_list(b.velocity));
  n.member("angular_velocity").set(json_list(b.angular_velocity));
  n.member("density").set(json_number(b.density));
  n.member("volume").set(json_number(shapes[k].mass.volume));
  n.member("mass").set(json_number(b.density * shapes[k].mass.volume));
}

}  // namespace

std::string scene_json(const Scene& scene) {
  const std::vector<Shape> shapes = build_scene_shapes(scene);
  Node root;
  root.member("format").set(json_string("lbdem-resolved-scene"));
  root.member("version").set("1");
  root.member("file").set(json_string(scene.file));
  char hash[20];
  std::snprintf(hash, sizeof(hash), "%016llx", static_cast<unsigned long long>(scene.hash));
  root.member("hash").set(json_string(hash));
  root.member("coupled").set(scene.coupled() ? "true" : "false");

  Node& tree = root.member("scene");
  for (const auto& k : scene.source->resolved) insert(tree, k.path, k.json);

  Node& derived = root.member("derived");
  if (scene.fluid)
    fluid_derived(derived.member("fluid"), *scene.fluid, !scene.bodies.empty());
  else
    derived.member("fluid").set("null");
  const double dt_fluid = scene.fluid ? scene.fluid->units.dt : 0;
  const double dt_dem = scene.dem ? dem_time_step(*scene.dem, shapes, scene.bodies) : 0;
  if (scene.dem)
    dem_derived(derived.member("dem"), scene, shapes, dt_dem);
  else
    derived.member("dem").set("null");
  schedule_derived(derived.member("schedule"), make_schedule(scene, dt_fluid, dt_dem),
                   scene.time.end);
  double solid = 0;
  for (const auto& b : scene.bodies) solid += shapes[static_cast<size_t>(b.shape)].mass.volume;
  Node& totals = derived.member("bodies");
  totals.member("count").set(json_int(static_cast<long long>(scene.bodies.size())));
  totals.member("solid_volume").set(json_number(solid));
  const auto box = dem_box(scene);
  double box_volume = box ? 1.0 : 0.0;
  for (int d = 0; box && d < 3; ++d) box_volume *= box->hi[d] - box->lo[d];
  totals.member("solid_fraction").set(box_volume > 0 ? json_number(solid / box_volume) : "null");

  Node& shape_list = root.member("shapes");
  shape_list.become(Node::Kind::array, "shapes");
  for (size_t i = 0; i < shapes.size(); ++i)
    shape_entry(shape_list.item(i), scene.shapes[i], shapes[i]);
  Node& body_list = root.member("bodies");
  body_list.become(Node::Kind::array, "bodies");
  for (size_t i = 0; i < scene.bodies.size(); ++i)
    body_entry(body_list.item(i), i, scene.bodies[i], scene, shapes);

  std::string out;
  // The scene, derived numbers and shapes spread over lines; each body on one line.
  write(root, out, 0, 1000);
  return out + "\n";
}

}  // namespace lbdem
