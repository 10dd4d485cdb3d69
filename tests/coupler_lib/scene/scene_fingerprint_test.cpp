#include "coupler_lib/scene/scene_fingerprint.hpp"

#include <gtest/gtest.h>

#include <string>

#include "coupler_lib/errors.hpp"

namespace lbdem {
namespace {

std::string scene_text(const std::string& end, const std::string& viscosity,
                       const std::string& coupling) {
  return "name: t\ntime: {end: " + end +
         "}\nfluid:\n  domain: [1.0, 1.0, 2.0]\n  dx: 0.125\n  viscosity: " + viscosity +
         "\n  tau: 0.6\ncoupling: {" + coupling + "}\n";
}

Scene parse(const std::string& text) {
  return parse_scene(Section::load_string(text, "t.yaml"), 0);
}

TEST(SceneFingerprint, KeysARestartMayChange) {
  for (const char* k :
       {"time.end", "log_level", "coupling.checkpoint_interval", "coupling.checkpoint_keep",
        "fluid.output.directory", "dem.output.interval", "coupling.output_interval",
        "coupling.stall_timeout", "fluid.stability.max_mach", "dem.max_overlap",
        "fluid.decomposition", "fluid.covered_cell_weight", "fluid.rebalance_above",
        "fluid.rebalance_interval"})
    EXPECT_TRUE(may_change_at_restart(k)) << k;
  for (const char* k : {"fluid.viscosity", "fluid.dx", "coupling.margin", "coupling.overlap",
                        "dem.gravity", "bodies.0.position"})
    EXPECT_FALSE(may_change_at_restart(k)) << k;
}

TEST(SceneFingerprint, SameForAnotherEndDifferentForAnotherViscosity) {
  const std::uint64_t base = scene_fingerprint(parse(scene_text("1.0", "1.0e-3", "")));
  EXPECT_EQ(base, scene_fingerprint(parse(scene_text(
                      "2.0", "1.0e-3", "checkpoint_interval: 0.5, checkpoint_keep: 3"))));
  EXPECT_NE(base, scene_fingerprint(parse(scene_text("1.0", "1.1e-3", ""))));
  EXPECT_NE(base, scene_fingerprint(parse(scene_text("1.0", "1.0e-3", "margin: 3"))));
}

TEST(SceneFingerprint, CheckpointKeysWithAndWithoutOverlap) {
  const Scene s = parse(scene_text("1.0", "1.0e-3", "checkpoint_interval: 0.5"));
  EXPECT_EQ(s.coupling.checkpoint_interval, 0.5);
  EXPECT_EQ(s.coupling.checkpoint_keep, 2);
  // With overlap the fluid waits for the states at every agreement step, so checkpoints work.
  const Scene o = parse(scene_text("1.0", "1.0e-3", "checkpoint_interval: 0.5, overlap: true"));
  EXPECT_TRUE(o.coupling.overlap);
  EXPECT_EQ(o.coupling.checkpoint_interval, 0.5);
  EXPECT_THROW(parse(scene_text("1.0", "1.0e-3", "checkpoint_keep: 0")), SceneError);
}

}  // namespace
}  // namespace lbdem
