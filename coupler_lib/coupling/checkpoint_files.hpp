#pragma once
// Where the checkpoints of a coupled run live, what every checkpoint file says about itself,
// and which of them a restart may use (docs/reliability.md, "Checkpoint and restart").
//
// A checkpoint is two files with a common prefix, one per program, written at the same
// exchange step:
//   <output dir>/<scene name>_checkpoints/<scene name>_step<S, 10 digits>.fluid.h5
//   <output dir>/<scene name>_checkpoints/<scene name>_step<S, 10 digits>.dem.h5
// (output dir: dem.output.directory, relative to the scene file). Each is written under a
// temporary name and renamed when complete, so a file with the final name is never half
// written. Every file carries the header below as HDF5 attributes on its root group.
#include <hdf5.h>

#include <cstdint>
#include <string>

#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

struct CheckpointHeader {
  std::string side;               // "fluid" or "dem"
  std::string version;            // program version (LBDEM_VERSION)
  std::uint64_t fingerprint = 0;  // scene_fingerprint of the scene that wrote it
  std::string scene_file;
  std::int64_t step = 0;  // exchange step the state belongs to (completed fluid steps)
  double time = 0;        // simulated s
  int fluid_ranks = 0;
  int dem_ranks = 0;
};

// The header of this program for `scene` at `step`.
CheckpointHeader make_checkpoint_header(const Scene& scene, const std::string& side,
                                        std::int64_t step, double time, int fluid_ranks,
                                        int dem_ranks);
void write_checkpoint_header(hid_t file, const CheckpointHeader& h);
// Throws std::runtime_error when an attribute is missing (not a checkpoint).
CheckpointHeader read_checkpoint_header(hid_t file);
// Opens `path` (one process, read-only) for its header. Throws std::runtime_error naming the
// file and what to do when it is unreadable, truncated or not a checkpoint.
CheckpointHeader read_checkpoint_header(const std::string& path);

std::string checkpoint_directory(const Scene& scene);
std::string checkpoint_prefix(const Scene& scene, std::int64_t step);
inline std::string fluid_half(const std::string& prefix) {
  return prefix + ".fluid.h5";
}
inline std::string dem_half(const std::string& prefix) {
  return prefix + ".dem.h5";
}

// The prefix `--restart ARG` names: ARG may be either half, the prefix itself, or a folder
// (its newest checkpoint with both halves). Throws SceneError-like std::runtime_error with
// what to do when nothing usable is there or a half is missing.
std::string restart_prefix(const std::string& arg);

// Checks one half's header against this run (the other program checks its own half):
// same side, version and scene fingerprint, and for `same_ranks_needed` the same rank count
// of this side. Throws std::runtime_error naming the file, what differs and what to do.
void check_checkpoint_header(const std::string& path, const CheckpointHeader& found,
                             const CheckpointHeader& expected, bool same_ranks_needed);

// What every rank of a program checks at start-up for `--restart ARG` (so that a refusal ends
// both programs cleanly, before they connect): the checkpoint exists with both halves, and
// this program's half has its side, the version, the scene fingerprint and, for the DEM,
// the DEM rank count of this run. Throws std::runtime_error with the message.
void check_restart(const std::string& arg, const Scene& scene, const std::string& side,
                   int side_ranks);

// Removes this side's halves (the DEM's with their journal parts) beyond the newest `keep` in
// the scene's checkpoint folder (called by one rank after a checkpoint is complete).
void prune_checkpoints(const Scene& scene, const std::string& side, int keep);

// The newest checkpoint this process completed or restarted from, for messages such as the
// stall watchdog's (empty: none).
void remember_checkpoint(const std::string& prefix);
const std::string& remembered_checkpoint();

// The command that continues the run from `prefix`, for the end-of-run message.
std::string restart_command(const Scene& scene, const std::string& prefix, int fluid_ranks,
                            int dem_ranks);

}  // namespace lbdem
