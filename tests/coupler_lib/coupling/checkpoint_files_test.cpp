#include "coupler_lib/coupling/checkpoint_files.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>

namespace lbdem {
namespace {

namespace fs = std::filesystem;

struct Folder {
  Folder() : dir(fs::temp_directory_path() / ("lbdem_ckpt_test_" + std::to_string(::getpid()))) {
    fs::remove_all(dir);
    fs::create_directories(dir / "s_checkpoints");
  }
  ~Folder() { fs::remove_all(dir); }
  void touch(const std::string& name) const { std::ofstream(dir / "s_checkpoints" / name) << "x"; }
  std::string at(const std::string& name) const { return (dir / "s_checkpoints" / name).string(); }
  fs::path dir;
};

Scene scene_in(const Folder& f) {
  Scene s;
  s.name.push_back('s');  // (not = "s": a GCC 12 -Wrestrict false positive)
  s.file = (f.dir / "s.yaml").string();
  s.dem.emplace();
  return s;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointFiles, NamesSortByStep) {
  const Folder f;
  const Scene s = scene_in(f);
  EXPECT_EQ(checkpoint_prefix(s, 40), f.at("s_step0000000040"));
  EXPECT_LT(checkpoint_prefix(s, 9), checkpoint_prefix(s, 10));
}

TEST(CheckpointFiles, RestartTakesTheNewestCompletePairOfAFolder) {
  const Folder f;
  f.touch("s_step0000000010.fluid.h5");
  f.touch("s_step0000000010.dem.h5");
  f.touch("s_step0000000020.fluid.h5");  // its DEM half never came
  EXPECT_EQ(restart_prefix(f.at("")), f.at("s_step0000000010"));
  EXPECT_EQ(restart_prefix(f.at("s_step0000000010.dem.h5")), f.at("s_step0000000010"));
  EXPECT_EQ(restart_prefix(f.at("s_step0000000010")), f.at("s_step0000000010"));
  const std::string m = message_of([&] { restart_prefix(f.at("s_step0000000020.fluid.h5")); });
  EXPECT_NE(m.find("s_step0000000020.dem.h5 is missing"), std::string::npos) << m;
  fs::remove(f.at("s_step0000000010.dem.h5"));
  EXPECT_NE(message_of([&] { restart_prefix(f.at("")); }).find("no complete checkpoint"),
            std::string::npos);
}

TEST(CheckpointFiles, PruneKeepsTheNewestOfItsOwnSide) {
  const Folder f;
  for (const char* name :
       {"s_step0000000010.fluid.h5", "s_step0000000010.dem.h5", "s_step0000000020.fluid.h5",
        "s_step0000000020.dem.h5", "s_step0000000030.fluid.h5", "s_step0000000030.dem.h5"})
    f.touch(name);
  prune_checkpoints(scene_in(f), "fluid", 2);
  EXPECT_FALSE(fs::exists(f.at("s_step0000000010.fluid.h5")));
  EXPECT_TRUE(fs::exists(f.at("s_step0000000010.dem.h5")));  // the DEM prunes its own
  EXPECT_TRUE(fs::exists(f.at("s_step0000000020.fluid.h5")));
  EXPECT_TRUE(fs::exists(f.at("s_step0000000030.fluid.h5")));
}

TEST(CheckpointFiles, PruneTakesTheDemJournalPartsWithTheirHalf) {
  const Folder f;
  for (const char* name : {"s_step0000000010.dem.h5", "s_step0000000010.dem.rank0.h5",
                           "s_step0000000010.dem.rank1.h5", "s_step0000000020.dem.h5",
                           "s_step0000000020.dem.rank0.h5", "s_step0000000020.dem.rank1.h5"})
    f.touch(name);
  prune_checkpoints(scene_in(f), "dem", 1);
  EXPECT_FALSE(fs::exists(f.at("s_step0000000010.dem.h5")));
  EXPECT_FALSE(fs::exists(f.at("s_step0000000010.dem.rank0.h5")));
  EXPECT_FALSE(fs::exists(f.at("s_step0000000010.dem.rank1.h5")));
  EXPECT_TRUE(fs::exists(f.at("s_step0000000020.dem.h5")));
  EXPECT_TRUE(fs::exists(f.at("s_step0000000020.dem.rank0.h5")));
  EXPECT_TRUE(fs::exists(f.at("s_step0000000020.dem.rank1.h5")));
}

TEST(CheckpointFiles, HeaderMismatchesSayWhatToChange) {
  CheckpointHeader expected;
  expected.side = "dem";
  expected.version = "0.1.0";
  expected.fingerprint = 1;
  expected.dem_ranks = 2;
  auto refusal = [&](CheckpointHeader found) {
    return message_of([&] { check_checkpoint_header("c.dem.h5", found, expected, true); });
  };
  EXPECT_EQ(refusal(expected), "");
  CheckpointHeader h = expected;
  h.version = "0.0.9";
  EXPECT_NE(refusal(h).find("written by version 0.0.9"), std::string::npos);
  h = expected;
  h.fingerprint = 2;
  EXPECT_NE(refusal(h).find("written for another scene"), std::string::npos);
  h = expected;
  h.side = "fluid";
  EXPECT_NE(refusal(h).find("it is the fluid half"), std::string::npos);
  h = expected;
  h.dem_ranks = 3;
  EXPECT_NE(refusal(h).find("use -np 3 for dem_app"), std::string::npos);
}

}  // namespace
}  // namespace lbdem
