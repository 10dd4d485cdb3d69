#pragma once
// The fingerprint a checkpoint carries: a hash of the resolved scene (every key with its
// effective value, as `--check` prints it) without the keys a restart may change, so that a
// run continued with a later time.end, other outputs or another log level still matches its
// checkpoint, and any change to the physics, the bodies or the lattice does not.
#include <cstdint>
#include <string>

#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

// True for a resolved key path that may differ between a run and its restart.
bool may_change_at_restart(const std::string& key_path);

// FNV-1a over "path=value\n" of every other resolved key, in reading order.
std::uint64_t scene_fingerprint(const Scene& scene);

}  // namespace lbdem
