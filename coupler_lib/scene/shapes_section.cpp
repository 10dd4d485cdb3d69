#include "coupler_lib/scene/shapes_section.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/stl_io.hpp"

namespace lbdem {

namespace {

// Relative paths in a scene are relative to the folder of the scene file.
std::string resolve(const Section& s, const std::string& file) {
  std::filesystem::path p(file);
  if (p.is_relative()) p = std::filesystem::path(s.file()).parent_path() / p;
  return p.lexically_normal().string();
}

std::string existing_file(Section& s, std::string_view key) {
  const auto file = s.require<std::string>(key);
  const auto path = resolve(s, file);
  if (std::filesystem::is_directory(path))
    s.fail(key, "'" + file + "' is a folder, expected a file (" + path + ")");
  if (!std::filesystem::is_regular_file(path))
    s.fail(key, "file '" + file + "' not found (looked for " + path + ")");
  return path;
}

const MappingSchema& clump_schema() {
  static const MappingSchema m{
      "shapes[].clump",
      "contact clump: {file: path} or {method: ...}",
      {key::choice("method", words_of(kClumpMethodWords),
                   "clump generator (or give 'file' instead)")
           .absent_means("give file instead")},
      {{"file",
        "",
        {key::text("file", "clump file, one sphere 'x y z r' per line").required(),
         key::number("scale", "multiplies clump coordinates and radii")
             .or_default(1.0)
             .within(Bounds::positive())},
        {}},
       {"method",
        "surface",
        {key::integer("grid", "grid points per edge of the bounding box")
             .required()
             .within(Bounds::at_least(2)),
         key::number("radius_ratio", "sphere radius / grid spacing")
             .or_default(1.0)
             .within(Bounds::positive()),
         key::boolean("center_sphere", "add the largest inscribed sphere at the centre")
             .or_default(true)},
        {}},
       {"method",
        "fill",
        {key::integer("spheres", "target number of spheres")
             .required()
             .within(Bounds::at_least(1))},
        {}}},
      {{"file", "method"}}};
  return m;
}

ClumpParams parse_clump(Section& c) {
  ClumpParams p;
  if (c.has("file")) {
    if (c.has("method"))
      c.fail("method", "give either 'file' (a clump file) or 'method' (generate), not both");
    p.source = ClumpSource::file;
    p.file = existing_file(c, "file");
    p.scale = c.get<double>("scale");
  } else {
    p.source = value_of(kClumpMethodWords, c.require_choice("method"));
    if (p.source == ClumpSource::fill) {
      p.spheres = c.require<int>("spheres");
    } else {
      p.grid = c.require<int>("grid");
      p.radius_ratio = c.get<double>("radius_ratio");
      p.center_sphere = c.get<bool>("center_sphere");
    }
  }
  c.finish();
  return p;
}

}  // namespace

const MappingSchema& shape_schema() {
  static const MappingSchema m{
      "shapes[]",
      "a body shape of the catalogue",
      {key::text("name", "shape name used by bodies").required(),
       key::choice("kind", words_of(kShapeKindWords), "shape kind").required(),
       key::number(
           "voxel_size",
           "voxel spacing in m of the shape's voxelization; the fluid's reference lattice has "
           "half of it (0: half the fluid spacing, the only value a scene with a fluid accepts; "
           "without a fluid any, 0: size/40)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("m"),
       key::number("hydrodynamic_scale",
                   "factor on the shape's size as the fluid sees it (1: the true shape; mass and "
                   "contacts always use the true shape)")
           .or_default(1.0)
           .within(Bounds::closed(0.5, 2.0)),
       key::section("clump", clump_schema(), "contact clump: {file: path} or {method: ...}")
           .absent_means("generated from the shape")},
      {{"kind",
        "sphere",
        {key::number("diameter", "sphere diameter in m")
             .required()
             .within(Bounds::positive())
             .in("m")},
        {}},
       {"kind",
        "cube",
        {key::number("edge", "cube edge in m").required().within(Bounds::positive()).in("m")},
        {}},
       {"kind",
        "cuboid",
        {key::vec3("edges", "cuboid edges [a, b, c] along x, y, z in m")
             .required()
             .within(Bounds::positive())
             .in("m")},
        {}},
       {"kind",
        "ellipsoid",
        {key::vec3("semi_axes", "ellipsoid semi-axes [a, b, c] along x, y, z in m")
             .required()
             .within(Bounds::positive())
             .in("m")},
        {}},
       {"kind",
        "stl",
        {key::text("file", "STL file (ASCII or binary), relative to the scene").required(),
         key::number("scale", "multiplies the STL coordinates (to m)")
             .or_default(1.0)
             .within(Bounds::positive())},
        {}}}};
  return m;
}

std::vector<ShapeParams> parse_shapes(Section& root) {
  std::vector<ShapeParams> out;
  std::set<std::string> names;
  for (auto& s : root.list("shapes")) {
    ShapeParams sh;
    sh.where = s.where("");
    sh.name = s.require<std::string>("name");
    if (!names.insert(sh.name).second)
      s.fail("name", "a shape named '" + sh.name + "' is already in the catalogue");
    sh.kind = value_of(kShapeKindWords, s.require_choice("kind"));
    if (sh.kind == ShapeKind::sphere) {
      sh.size = s.require<double>("diameter");
      sh.extents = {sh.size / 2, sh.size / 2, sh.size / 2};
    } else if (sh.kind == ShapeKind::cube) {
      sh.size = s.require<double>("edge");
      sh.extents = {sh.size, sh.size, sh.size};
    } else if (sh.kind == ShapeKind::cuboid) {
      sh.extents = s.require_vec3("edges");
      sh.size = *std::max_element(sh.extents.begin(), sh.extents.end());
    } else if (sh.kind == ShapeKind::ellipsoid) {
      sh.extents = s.require_vec3("semi_axes");
      sh.size = 2 * *std::max_element(sh.extents.begin(), sh.extents.end());
    } else {
      sh.file = existing_file(s, "file");
      sh.scale = s.get<double>("scale");
      try {
        TriangleMesh mesh = read_stl(sh.file);
        Eigen::Vector3d lo, hi;
        bounding_box(mesh, lo, hi);
        sh.size = (hi - lo).maxCoeff() * sh.scale;
        sh.extents = {(hi - lo).x() * sh.scale, (hi - lo).y() * sh.scale, (hi - lo).z() * sh.scale};
      } catch (const ShapeError& e) {
        s.fail("file", e.what());
      }
    }
    sh.voxel_size = s.get<double>("voxel_size");
    sh.hydrodynamic_scale = s.get<double>("hydrodynamic_scale");
    if (auto c = s.optional_section("clump"))
      sh.clump = parse_clump(*c);
    else
      sh.clump.source = ClumpSource::shape_default;
    s.finish();
    out.push_back(sh);
  }
  return out;
}

}  // namespace lbdem
