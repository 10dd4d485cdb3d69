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

std::string existing_file(Section& s, std::string_view key, std::string_view doc) {
  const auto file = s.require<std::string>(key, doc);
  const auto path = resolve(s, file);
  if (std::filesystem::is_directory(path))
    s.fail(key, "'" + file + "' is a folder, expected a file (" + path + ")");
  if (!std::filesystem::is_regular_file(path))
    s.fail(key, "file '" + file + "' not found (looked for " + path + ")");
  return path;
}

ClumpParams parse_clump(Section& c) {
  ClumpParams p;
  if (c.has("file")) {
    if (c.has("method"))
      c.fail("method", "give either 'file' (a clump file) or 'method' (generate), not both");
    p.source = "file";
    p.file = existing_file(c, "file", "clump file, one sphere 'x y z r' per line");
    p.scale =
        c.get<double>("scale", 1.0, "multiplies clump coordinates and radii", Bounds::positive());
  } else {
    p.source =
        c.require_choice("method", {"surface", "fill"}, "clump generator (or give 'file' instead)");
    if (p.source == "fill") {
      p.spheres = c.require<int>("spheres", "target number of spheres", Bounds::at_least(1));
    } else {
      p.grid =
          c.require<int>("grid", "grid points per edge of the bounding box", Bounds::at_least(2));
      p.radius_ratio =
          c.get<double>("radius_ratio", 1.0, "sphere radius / grid spacing", Bounds::positive());
      p.center_sphere =
          c.get<bool>("center_sphere", true, "add the largest inscribed sphere at the centre");
    }
  }
  c.finish();
  return p;
}

}  // namespace

std::vector<ShapeParams> parse_shapes(Section& root) {
  std::vector<ShapeParams> out;
  std::set<std::string> names;
  for (auto& s : root.list("shapes", "catalogue of body shapes")) {
    ShapeParams sh;
    sh.where = s.where("");
    sh.name = s.require<std::string>("name", "shape name used by bodies");
    if (!names.insert(sh.name).second)
      s.fail("name", "a shape named '" + sh.name + "' is already in the catalogue");
    sh.kind =
        s.require_choice("kind", {"sphere", "cube", "cuboid", "ellipsoid", "stl"}, "shape kind");
    if (sh.kind == "sphere") {
      sh.size = s.require<double>("diameter", "sphere diameter in m", Bounds::positive());
      sh.extents = {sh.size / 2, sh.size / 2, sh.size / 2};
    } else if (sh.kind == "cube") {
      sh.size = s.require<double>("edge", "cube edge in m", Bounds::positive());
      sh.extents = {sh.size, sh.size, sh.size};
    } else if (sh.kind == "cuboid") {
      sh.extents =
          s.require_vec3("edges", "cuboid edges [a, b, c] along x, y, z in m", Bounds::positive());
      sh.size = *std::max_element(sh.extents.begin(), sh.extents.end());
    } else if (sh.kind == "ellipsoid") {
      sh.extents = s.require_vec3("semi_axes", "ellipsoid semi-axes [a, b, c] along x, y, z in m",
                                  Bounds::positive());
      sh.size = 2 * *std::max_element(sh.extents.begin(), sh.extents.end());
    } else {
      sh.file = existing_file(s, "file", "STL file (ASCII or binary), relative to the scene");
      sh.scale =
          s.get<double>("scale", 1.0, "multiplies the STL coordinates (to m)", Bounds::positive());
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
    sh.voxel_size = s.get<double>("voxel_size", 0.0,
                                  "voxel spacing in m (0: half the fluid spacing, or size/40 "
                                  "without a fluid)",
                                  Bounds::non_negative());
    sh.hydrodynamic_scale = s.get<double>(
        "hydrodynamic_scale", 1.0,
        "factor on the shape's size as the fluid sees it (1: the true shape; mass and contacts "
        "always use the true shape)",
        Bounds::closed(0.5, 2.0));
    if (auto c = s.optional_section("clump", "contact clump: {file: path} or {method: ...}"))
      sh.clump = parse_clump(*c);
    else
      sh.clump.source = "default";
    s.finish();
    out.push_back(sh);
  }
  return out;
}

}  // namespace lbdem
