#include "coupler_lib/coupling/checkpoint_files.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "coupler_lib/output/hdf5_handle.hpp"
#include "coupler_lib/scene/scene_fingerprint.hpp"

namespace lbdem {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFluidSuffix = ".fluid.h5";
constexpr const char* kDemSuffix = ".dem.h5";

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string hex(std::uint64_t v) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// Prefixes of the halves of `side` ("fluid", "dem" or "both": both halves present) in `dir`,
// oldest first (the step is zero-padded, so the names sort by step).
std::vector<std::string> prefixes_in(const fs::path& dir, const std::string& side) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string p = e.path().string();
    if (!ends_with(p, kFluidSuffix)) {
      if (side == "dem" && ends_with(p, kDemSuffix))
        out.push_back(p.substr(0, p.size() - std::string(kDemSuffix).size()));
      continue;
    }
    const std::string prefix = p.substr(0, p.size() - std::string(kFluidSuffix).size());
    if (side == "fluid" || (side == "both" && fs::exists(dem_half(prefix)))) out.push_back(prefix);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

CheckpointHeader make_checkpoint_header(const Scene& scene, const std::string& side,
                                        std::int64_t step, double time, int fluid_ranks,
                                        int dem_ranks) {
  CheckpointHeader h;
  h.side = side;
  h.version = LBDEM_VERSION;
  h.fingerprint = scene_fingerprint(scene);
  h.scene_file = scene.file;
  h.step = step;
  h.time = time;
  h.fluid_ranks = fluid_ranks;
  h.dem_ranks = dem_ranks;
  return h;
}

void write_checkpoint_header(hid_t file, const CheckpointHeader& h) {
  write_attribute(file, "checkpoint_side", h.side);
  write_attribute(file, "checkpoint_program_version", h.version);
  // As text: an HDF5 attribute has no unsigned 64-bit scalar in this layer.
  write_attribute(file, "checkpoint_scene_fingerprint", hex(h.fingerprint));
  write_attribute(file, "checkpoint_scene_file", h.scene_file);
  write_attribute(file, "checkpoint_step", static_cast<long long>(h.step));
  write_attribute(file, "checkpoint_time", h.time);
  write_attribute(file, "checkpoint_fluid_ranks", static_cast<long long>(h.fluid_ranks));
  write_attribute(file, "checkpoint_dem_ranks", static_cast<long long>(h.dem_ranks));
}

CheckpointHeader read_checkpoint_header(hid_t file) {
  CheckpointHeader h;
  h.side = read_string_attribute(file, "checkpoint_side");
  h.version = read_string_attribute(file, "checkpoint_program_version");
  h.fingerprint =
      std::stoull(read_string_attribute(file, "checkpoint_scene_fingerprint"), nullptr, 16);
  h.scene_file = read_string_attribute(file, "checkpoint_scene_file");
  h.step = read_llong_attribute(file, "checkpoint_step");
  h.time = read_double_attribute(file, "checkpoint_time");
  h.fluid_ranks = static_cast<int>(read_llong_attribute(file, "checkpoint_fluid_ranks"));
  h.dem_ranks = static_cast<int>(read_llong_attribute(file, "checkpoint_dem_ranks"));
  return h;
}

CheckpointHeader read_checkpoint_header(const std::string& path) {
  try {
    const hid_t id = [&] {
      const QuietHdf5 quiet;
      return H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    }();
    const H5Handle file(id, H5Fclose, "opening " + path);
    return read_checkpoint_header(file);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot restart from " + path +
                             ": not a readable checkpoint (truncated, overwritten or not one: " +
                             e.what() + "); give an older checkpoint of the folder");
  }
}

void check_restart(const std::string& arg, const Scene& scene, const std::string& side,
                   int side_ranks) {
  if (!scene.coupled())
    throw std::runtime_error("--restart continues a coupled run; " + scene.file +
                             " is not a coupled scene");
  const std::string prefix = restart_prefix(arg);
  const std::string path = side == "fluid" ? fluid_half(prefix) : dem_half(prefix);
  const CheckpointHeader found = read_checkpoint_header(path);
  const CheckpointHeader expected = make_checkpoint_header(
      scene, side, 0, 0, side == "fluid" ? side_ranks : 0, side == "dem" ? side_ranks : 0);
  check_checkpoint_header(path, found, expected, true);
}

std::string checkpoint_directory(const Scene& scene) {
  fs::path dir(scene.dem ? scene.dem->output.directory : std::string("."));
  if (dir.is_relative()) dir = fs::path(scene.file).parent_path() / dir;
  return (dir / (scene.name + "_checkpoints")).lexically_normal().string();
}

std::string checkpoint_prefix(const Scene& scene, std::int64_t step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_step%010lld", static_cast<long long>(step));
  return (fs::path(checkpoint_directory(scene)) / (scene.name + buf)).string();
}

std::string restart_prefix(const std::string& arg) {
  std::string prefix = arg;
  if (fs::is_directory(arg)) {
    const auto all = prefixes_in(arg, "both");
    if (all.empty())
      throw std::runtime_error("--restart " + arg +
                               ": the folder holds no complete checkpoint "
                               "(no pair of *.fluid.h5 and *.dem.h5 files)");
    prefix = all.back();
  } else if (ends_with(arg, kFluidSuffix)) {
    prefix = arg.substr(0, arg.size() - std::string(kFluidSuffix).size());
  } else if (ends_with(arg, kDemSuffix)) {
    prefix = arg.substr(0, arg.size() - std::string(kDemSuffix).size());
  }
  for (const std::string& half : {fluid_half(prefix), dem_half(prefix)})
    if (!fs::is_regular_file(half))
      throw std::runtime_error(
          "--restart " + arg + ": " + half +
          " is missing; a restart needs both halves of one "
          "checkpoint (the fluid and the DEM file of the same step): give the folder to take "
          "the newest complete one");
  return prefix;
}

void check_checkpoint_header(const std::string& path, const CheckpointHeader& found,
                             const CheckpointHeader& expected, bool same_ranks_needed) {
  auto refuse = [&](const std::string& what) {
    throw std::runtime_error("cannot restart from " + path + ": " + what);
  };
  if (found.side != expected.side)
    refuse("it is the " + found.side + " half, this program needs the " + expected.side + " half");
  if (found.version != expected.version)
    refuse("written by version " + found.version + ", this program is version " + expected.version +
           "; continue the run with the version that wrote it");
  if (found.fingerprint != expected.fingerprint)
    refuse("written for another scene ('" + found.scene_file + "', fingerprint " +
           hex(found.fingerprint) + "; this scene '" + expected.scene_file + "' has " +
           hex(expected.fingerprint) +
           "); only time.end, outputs, log, checkpoint and fluid layout keys may change at a "
           "restart");
  if (same_ranks_needed && found.side == "dem" && found.dem_ranks != expected.dem_ranks)
    refuse("written by " + std::to_string(found.dem_ranks) + " dem_app ranks, this run has " +
           std::to_string(expected.dem_ranks) +
           "; the DEM side restarts bit for bit only on the same rank count: use -np " +
           std::to_string(found.dem_ranks) + " for dem_app");
}

void prune_checkpoints(const Scene& scene, const std::string& side, int keep) {
  const auto all = prefixes_in(checkpoint_directory(scene), side);
  const std::string suffix = side == "fluid" ? kFluidSuffix : kDemSuffix;
  std::vector<std::string> pruned;
  for (std::size_t i = 0; i + static_cast<std::size_t>(keep) < all.size(); ++i) {
    std::error_code ec;
    fs::remove(all[i] + suffix, ec);
    pruned.push_back(all[i]);
  }
  if (side != "dem" || pruned.empty()) return;
  // The DEM half's journal parts, one per DEM rank: "<prefix>.dem.rank<k>.h5".
  std::error_code ec;
  std::vector<fs::path> parts;
  for (const auto& e : fs::directory_iterator(checkpoint_directory(scene), ec)) {
    const std::string p = e.path().string();
    for (const std::string& prefix : pruned)
      if (p.rfind(prefix + ".dem.rank", 0) == 0 && ends_with(p, ".h5")) parts.push_back(e.path());
  }
  for (const fs::path& p : parts) fs::remove(p, ec);
}

namespace {
std::string& remembered() {
  static std::string prefix;
  return prefix;
}
}  // namespace

void remember_checkpoint(const std::string& prefix) {
  remembered() = prefix;
}

const std::string& remembered_checkpoint() {
  return remembered();
}

std::string restart_command(const Scene& scene, const std::string& prefix, int fluid_ranks,
                            int dem_ranks) {
  std::ostringstream s;
  s << "mpirun -np " << fluid_ranks << " fluid_app --restart " << prefix << " " << scene.file
    << " : -np " << dem_ranks << " dem_app --restart " << prefix << " " << scene.file;
  return s.str();
}

}  // namespace lbdem
