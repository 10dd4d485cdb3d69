// clump_gen: shape (analytic or STL) -> multi-sphere clump file, with its shape errors.
// Also exports the analytic shapes as STL (the shipped configs/shapes/*.stl come from here).
// See docs/user-guide.md ("Clump generator") for the methods, the file format and the measured
// errors.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/build_shape.hpp"
#include "coupler_lib/geometry/clump_generator.hpp"
#include "coupler_lib/geometry/clump_io.hpp"
#include "coupler_lib/geometry/mass_properties.hpp"
#include "coupler_lib/geometry/mesh_primitives.hpp"
#include "coupler_lib/geometry/stl_io.hpp"
#include "coupler_lib/geometry/voxelize.hpp"

namespace {

using namespace lbdem;

constexpr const char* kUsage = R"(usage:
  clump_gen SHAPE --method surface --grid N [--radius-ratio R] [--no-center-sphere]
            [--voxels M] --out FILE.clump
  clump_gen SHAPE --method fill --spheres N [--voxels M] --out FILE.clump
  clump_gen SHAPE --export-stl FILE.stl [--binary] [--ico-levels L]
SHAPE:
  --shape sphere --diameter D | --shape cube --edge A | --shape cuboid --edges A,B,C |
  --shape ellipsoid --semi-axes A,B,C | --stl FILE [--scale S]
  --voxels M   voxels across the longest bounding-box edge, for the fill method and the
               error measurement (default 81)
  --ico-levels refinements of the icosahedron for a sphere/ellipsoid STL (default 3)
)";

struct Options {
  ShapeParams shape;
  std::optional<ClumpSource> method;  // surface | fill
  int grid = 0;
  double radius_ratio = 1.0;
  bool center_sphere = true;
  int spheres = 0;
  int voxels = 81;
  std::string out;
  std::string export_stl;
  bool binary = false;
  int ico_levels = 3;
  std::string command;
};

double number(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(v > 0))
    throw std::invalid_argument(flag + ": expected a positive number, got '" + text + "'");
  return v;
}

int integer(const std::string& flag, const std::string& text, int min) {
  const double v = number(flag, text);
  if (v != static_cast<int>(v) || v < min)
    throw std::invalid_argument(flag + ": expected an integer >= " + std::to_string(min) +
                                ", got '" + text + "'");
  return static_cast<int>(v);
}

std::array<double, 3> triple(const std::string& flag, const std::string& text) {
  std::array<double, 3> v{};
  std::stringstream ss(text);
  std::string part;
  int i = 0;
  while (std::getline(ss, part, ',')) {
    if (i == 3) break;
    v[i++] = number(flag, part);
  }
  if (i != 3 || std::getline(ss, part, ','))
    throw std::invalid_argument(flag + ": expected three comma-separated numbers, got '" + text +
                                "'");
  return v;
}

Options parse(int argc, char** argv) {
  Options o;
  o.command = "clump_gen";
  for (int i = 1; i < argc; ++i) o.command += std::string(" ") + argv[i];
  auto& s = o.shape;
  s.name = "shape";
  s.where = "clump_gen";
  std::optional<ShapeKind> kind;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + ": missing value");
      return argv[++i];
    };
    if (a == "--shape") {
      const std::string word = value();
      kind = find_word(kShapeKindWords, word);
      if (!kind || *kind == ShapeKind::stl)
        throw std::invalid_argument("--shape: expected sphere, cube, cuboid or ellipsoid, got '" +
                                    word + "' (use --stl FILE for meshes)");
    } else if (a == "--diameter" || a == "--edge") {
      s.size = number(a, value());
      s.extents = {s.size, s.size, s.size};
      if (a == "--diameter") s.extents = {s.size / 2, s.size / 2, s.size / 2};
    } else if (a == "--edges" || a == "--semi-axes") {
      s.extents = triple(a, value());
      const double m = std::max({s.extents[0], s.extents[1], s.extents[2]});
      s.size = a == "--edges" ? m : 2 * m;
    } else if (a == "--stl") {
      kind = ShapeKind::stl;
      s.file = value();
    } else if (a == "--scale") {
      s.scale = number(a, value());
    } else if (a == "--method") {
      const std::string word = value();
      o.method = find_word(kClumpMethodWords, word);
      if (!o.method)
        throw std::invalid_argument("--method: expected surface or fill, got '" + word + "'");
    } else if (a == "--grid") {
      o.grid = integer(a, value(), 2);
    } else if (a == "--radius-ratio") {
      o.radius_ratio = number(a, value());
    } else if (a == "--no-center-sphere") {
      o.center_sphere = false;
    } else if (a == "--spheres") {
      o.spheres = integer(a, value(), 1);
    } else if (a == "--voxels") {
      o.voxels = integer(a, value(), 8);
    } else if (a == "--out") {
      o.out = value();
    } else if (a == "--export-stl") {
      o.export_stl = value();
    } else if (a == "--binary") {
      o.binary = true;
    } else if (a == "--ico-levels") {
      o.ico_levels = integer(a, value(), 0);
    } else if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else {
      throw std::invalid_argument("unknown argument '" + a + "'");
    }
  }
  if (!kind) throw std::invalid_argument("give a shape: --shape KIND ... or --stl FILE");
  s.kind = *kind;
  if (s.kind != ShapeKind::stl && !(s.size > 0))
    throw std::invalid_argument("--shape " + std::string(word_of(kShapeKindWords, s.kind)) +
                                " needs its size (" +
                                (s.kind == ShapeKind::sphere   ? "--diameter"
                                 : s.kind == ShapeKind::cube   ? "--edge"
                                 : s.kind == ShapeKind::cuboid ? "--edges"
                                                               : "--semi-axes") +
                                ")");
  if (!o.export_stl.empty()) return o;
  if (!o.method) throw std::invalid_argument("give --method surface|fill or --export-stl");
  if (*o.method == ClumpSource::surface && o.grid == 0)
    throw std::invalid_argument("--method surface needs --grid N");
  if (*o.method == ClumpSource::fill && o.spheres == 0)
    throw std::invalid_argument("--method fill needs --spheres N");
  if (o.out.empty()) throw std::invalid_argument("give the output file: --out FILE.clump");
  return o;
}

void export_stl(const Options& o) {
  const auto& s = o.shape;
  const Eigen::Vector3d e(s.extents[0], s.extents[1], s.extents[2]);
  TriangleMesh mesh;
  if (s.kind == ShapeKind::stl)
    throw std::invalid_argument("--export-stl needs an analytic --shape");
  if (!extents_are_semi_axes(s.kind)) {
    mesh = box_mesh(e);
  } else {
    mesh = icosphere_mesh(1.0, o.ico_levels);
    transform_mesh(mesh, e.asDiagonal(), Eigen::Vector3d::Zero());
  }
  o.binary ? write_stl_binary(o.export_stl, mesh)
           : write_stl_ascii(o.export_stl, mesh, std::string(word_of(kShapeKindWords, s.kind)));
  std::printf("%s: %zu triangles, volume %.6g (analytic %.6g)\n", o.export_stl.c_str(),
              mesh.triangles.size(), signed_volume(mesh), make_solid(s).exact_volume());
}

void generate(const Options& o) {
  const SolidGeometry solid = make_solid(o.shape);
  const double L = (solid.upper() - solid.lower()).maxCoeff();
  const double h = L / o.voxels;
  const Voxels vox = voxelize(solid, h, 3);
  const MassProperties mass = mass_properties(solid);
  const Clump clump = *o.method == ClumpSource::surface
                          ? surface_clump(solid, vox, {o.grid, o.radius_ratio, o.center_sphere})
                          : fill_clump(solid, vox, {o.spheres});
  const ClumpQuality q = clump_quality(clump, vox);
  std::ostringstream method, lattice, err, dev;
  if (*o.method == ClumpSource::surface)
    method << "method: surface grid=" << o.grid << " radius_ratio=" << o.radius_ratio
           << " center_sphere=" << (o.center_sphere ? "yes" : "no");
  else
    method << "method: fill spheres=" << o.spheres;
  lattice.precision(6);
  lattice << "lattice: h=" << h << " (" << o.voxels << " voxels across " << L << "), voxel volume "
          << mass_properties(vox).volume << ", exact volume " << mass.volume;
  err << "volume_error: " << q.volume_error
      << "  (|clump union XOR shape| / shape volume, enclosed cavities filled)";
  dev << "max_surface_deviation: " << q.max_deviation << "  (" << q.max_deviation / L
      << " of the size; two-sided, +-h/2)";
  const std::vector<std::string> header = {
      "lbdem clump file: one sphere per line, x y z r, shape frame (voxel centroid at origin)",
      "shape: " + (o.shape.kind == ShapeKind::stl
                       ? o.shape.file + " scale " + std::to_string(o.shape.scale)
                       : solid.describe()),
      method.str(),
      "spheres: " + std::to_string(clump.size()),
      lattice.str(),
      err.str(),
      dev.str(),
      "generated by: " + o.command};
  write_clump(o.out, translated(clump, mass.centroid), header);
  std::printf("%s: %zu spheres, volume error %.4f, max surface deviation %.4g (%.4f of %g)\n",
              o.out.c_str(), clump.size(), q.volume_error, q.max_deviation, q.max_deviation / L, L);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    if (!o.export_stl.empty())
      export_stl(o);
    else
      generate(o);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "clump_gen: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "clump_gen: %s\n", e.what());
    return 1;
  }
  return 0;
}
