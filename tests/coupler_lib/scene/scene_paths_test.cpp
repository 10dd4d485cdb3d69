// Names and paths of a scene refused when it is read, and the checks between its sections
// (coupler_lib/scene/scene_paths.hpp, section_agreement.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "coupler_lib/scene/scene.hpp"

namespace lbdem {
namespace {

namespace fs = std::filesystem;

const std::string kCoupled = R"(
name: t
time: {end: 1.0e-3}
fluid:
  domain: [1.0e-3, 1.0e-3, 1.0e-3]
  dx: 1.0e-4
  viscosity: 1.0e-6
  tau: 0.6
dem:
  periodic: xyz
shapes:
  - {name: ball, kind: sphere, diameter: 3.0e-4}
bodies:
  - {shape: ball, position: [5.0e-4, 5.0e-4, 5.0e-4], density: 2500}
)";

// The message of the SceneError that parsing `text` as `file` throws (empty: none).
std::string refusal(const std::string& text, const std::string& file = "t.yaml") {
  try {
    parse_scene(Section::load_string(text, file), 0);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

std::string with_name(const std::string& name) {
  std::string t = kCoupled;
  return t.replace(t.find("name: t"), 7, "name: '" + name + "'");
}

TEST(ScenePaths, ANameMustBeAPlainFileName) {
  for (const char* bad : {"../escape", "out/x", "..", ".", "", "a b", "tab\there", "semi;colon"}) {
    const std::string m = refusal(with_name(bad));
    EXPECT_NE(m.find("t.yaml:2: name: '" + std::string(bad) + "' is not a plain file name"),
              std::string::npos)
        << bad << ": " << m;
  }
  for (const char* good : {"t", "sphere_phi0.100", "run-2.b", "A9"})
    EXPECT_EQ(refusal(with_name(good)), "") << good;
}

class ScenePathsOnDisk : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() /
        ("lbdem_scene_paths_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "a_file") << "x";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string scene_file() const { return (dir_ / "scene.yaml").string(); }
  fs::path dir_;
};

TEST_F(ScenePathsOnDisk, AnOutputDirectoryThatIsAFileIsRefused) {
  std::string t = kCoupled;
  t.insert(t.find("dem:"), "  output: {directory: a_file}\n");
  const std::string m = refusal(t, scene_file());
  EXPECT_NE(m.find(":9: fluid.output.directory: '"), std::string::npos) << m;
  EXPECT_NE(m.find("a_file' exists and is not a directory"), std::string::npos) << m;

  std::string d = kCoupled;
  d.insert(d.find("shapes:"), "  output: {directory: a_file/below}\n");
  const std::string md = refusal(d, scene_file());
  EXPECT_NE(md.find(": dem.output.directory: '"), std::string::npos) << md;
  EXPECT_NE(md.find("cannot be created: '"), std::string::npos) << md;
  EXPECT_NE(md.find("a_file' is not a directory"), std::string::npos) << md;
}

TEST_F(ScenePathsOnDisk, AMissingOutputDirectoryBelowAWritableOneIsAccepted) {
  std::string t = kCoupled;
  t.insert(t.find("dem:"), "  output: {directory: new/deeper, series: {interval: 1.0e-4}}\n");
  EXPECT_EQ(refusal(t, scene_file()), "");
  EXPECT_FALSE(fs::exists(dir_ / "new"));  // checking creates nothing
}

TEST_F(ScenePathsOnDisk, ARecordingOrLastGoodFileWhereAFolderIsIsRefused) {
  fs::create_directories(dir_ / "folder");
  const std::string m = refusal(kCoupled + "coupling: {record: folder}\n", scene_file());
  EXPECT_NE(m.find(": coupling.record: '"), std::string::npos) << m;
  EXPECT_NE(m.find("folder' is a directory; name a file"), std::string::npos) << m;

  std::string t = kCoupled;
  t.insert(t.find("dem:"), "  stability: {last_good: folder}\n");
  const std::string ml = refusal(t, scene_file());
  EXPECT_NE(ml.find("fluid.stability.last_good: '"), std::string::npos) << ml;
}

TEST_F(ScenePathsOnDisk, TheRecordingIsResolvedAgainstTheScenesFolder) {
  const Scene s =
      parse_scene(Section::load_string(kCoupled + "coupling: {record: rec.h5}\n", scene_file()), 0);
  EXPECT_EQ(s.coupling.record, (dir_ / "rec.h5").string());
}

TEST(SectionAgreement, PeriodicAxesOfFluidAndDemMustAgree) {
  std::string t = kCoupled;
  t.insert(t.find("dem:"), "  boundaries: {z_min: wall, z_max: wall}\n");
  const std::string m = refusal(t);
  EXPECT_NE(m.find("t.yaml:11: dem.periodic: periodic on 'xyz' but fluid.boundaries on 'xy': "
                   "they disagree along z"),
            std::string::npos)
      << m;
  // Without bodies the scene is not coupled: the fluid runs alone and the DEM's axes do not matter.
  EXPECT_EQ(refusal(t.substr(0, t.find("shapes:"))), "");
}

TEST(SectionAgreement, BuoyancyOfTheDemOnlyInDemOnlyScenesAndTheirBox) {
  std::string t = kCoupled;
  t.insert(t.find("shapes:"), "  buoyancy_fluid_density: 1000\n");
  EXPECT_NE(refusal(t).find("dem.buoyancy_fluid_density: only for DEM-only scenes"),
            std::string::npos);
  const std::string dem_only = "name: t\ntime: {end: 1.0}\ndem:\n  gravity: [0, 0, -9.81]\n" +
                               kCoupled.substr(kCoupled.find("shapes:"));
  EXPECT_NE(refusal(dem_only).find("t.yaml:4: dem.box: required when the scene has no fluid"),
            std::string::npos)
      << refusal(dem_only);
}

}  // namespace
}  // namespace lbdem
