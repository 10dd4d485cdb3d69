#include <gtest/gtest.h>

#include <cmath>

#include "coupler_lib/scene/scene.hpp"

namespace lbdem {
namespace {

const char* kMinimal = R"(
name: t
time: {end: 1.0}
fluid:
  domain: [1.0, 1.0, 2.0]
  dx: 0.125
  viscosity: 1.0e-3
  tau: 0.6
)";

Scene parse(const std::string& text) {
  return parse_scene(Section::load_string(text, "t.yaml"), 0);
}

TEST(Scene, ParsesMinimalFluidScene) {
  Scene s = parse(kMinimal);
  ASSERT_TRUE(s.fluid);
  EXPECT_EQ(s.fluid->cells[2], 16);
  EXPECT_FALSE(s.dem);
}

TEST(Scene, UnknownKeyGetsSuggestionAndLine) {
  std::string text = std::string(kMinimal) + "  viscosty: 3\n";
  try {
    parse(text);
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("t.yaml:9"), std::string::npos) << m;
    EXPECT_NE(m.find("fluid.viscosty"), std::string::npos) << m;
    EXPECT_NE(m.find("did you mean 'viscosity'"), std::string::npos) << m;
  }
}

TEST(Scene, OutOfRangeValueNamesBounds) {
  std::string text = kMinimal;
  text.replace(text.find("tau: 0.6"), 8, "tau: 0.5");
  try {
    parse(text);
    FAIL();
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("fluid.tau"), std::string::npos) << m;
    EXPECT_NE(m.find("> 0.5"), std::string::npos) << m;
  }
}

TEST(Scene, LoadMethodAndControllerKeys) {
  // Default: loads from the penalization; the controller every step with feed-forward.
  Scene s = parse(kMinimal);
  EXPECT_EQ(s.fluid->loads, LoadMethod::penalization);
  s = parse(std::string(kMinimal) + "  loads: momentum_exchange\n");
  EXPECT_EQ(s.fluid->loads, LoadMethod::momentum_exchange);
  try {
    parse(std::string(kMinimal) + "  loads: surface\n");
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("fluid.loads"), std::string::npos) << m;
    EXPECT_NE(m.find("penalization"), std::string::npos) << m;
  }
  // The paper's form f <- f - K_p <v> (gain 0, integral gain K_p) every `interval` seconds.
  s = parse(std::string(kMinimal) +
            "  mean_velocity_control: {gain: 0, integral_gain: 0.01, interval: 2.0e-3, "
            "feed_forward: false}\n");
  const double dt = s.fluid->units.dt;
  EXPECT_EQ(s.fluid->control.every, std::max(1L, std::lround(2.0e-3 / dt)));
  EXPECT_FALSE(s.fluid->control.feed_forward);
  EXPECT_EQ(s.fluid->control.gain, 0.0);
  EXPECT_THROW(parse(std::string(kMinimal) + "  mean_velocity_control: {interval: -1}\n"),
               SceneError);
}

TEST(Scene, WrongTypeAndMissingKey) {
  std::string text = kMinimal;
  text.replace(text.find("dx: 0.125"), 9, "dx: fine");
  EXPECT_THROW(parse(text), SceneError);
  EXPECT_THROW(parse("time: {end: 1}\nfluid: {domain: [1,1,1], viscosity: 1}\n"), SceneError);
}

// fluid.porosity_lookup and dem.dt_rule: each value is read, anything else is refused with
// the key and the admissible values.
TEST(Scene, PorosityLookupAndDemStepRuleAreChoices) {
  EXPECT_EQ(parse(kMinimal).fluid->porosity_lookup, PorosityLookup::nearest);
  Scene s =
      parse(std::string(kMinimal) + "  porosity_lookup: trilinear\ndem: {dt_rule: particle}\n");
  EXPECT_EQ(s.fluid->porosity_lookup, PorosityLookup::trilinear);
  EXPECT_EQ(s.dem->dt_rule, DtRule::particle);
  EXPECT_EQ(parse(std::string(kMinimal) + "dem: {}\n").dem->dt_rule, DtRule::clump_sphere);
  for (const std::string bad : {"  porosity_lookup: cubic\n", "dem: {dt_rule: body}\n"}) {
    try {
      parse(std::string(kMinimal) + bad);
      FAIL() << "expected a SceneError for " << bad;
    } catch (const SceneError& e) {
      const std::string m = e.what();
      const bool fluid = bad.find("porosity") != std::string::npos;
      EXPECT_NE(m.find(fluid ? "fluid.porosity_lookup" : "dem.dt_rule"), std::string::npos) << m;
      EXPECT_NE(m.find(fluid ? "nearest" : "particle"), std::string::npos) << m;
    }
  }
}

std::string message_of(const std::string& text) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, NonFiniteNumbersAreRefused) {
  for (const char* bad : {".inf", "-.inf", ".nan", ".Inf"}) {
    std::string text = kMinimal;
    text.replace(text.find("1.0e-3"), 6, bad);
    const std::string m = message_of(text);
    EXPECT_NE(m.find("fluid.viscosity: expected a finite number"), std::string::npos) << bad << m;
  }
  // Beyond the range of a double: yaml-cpp cannot convert it at all.
  std::string text = kMinimal;
  text.replace(text.find("1.0e-3"), 6, "1e999");
  EXPECT_NE(message_of(text).find("fluid.viscosity: expected a number, got '1e999'"),
            std::string::npos);
}

TEST(Scene, DuplicateKeysAreRefusedWithTheirLine) {
  const std::string m = message_of(std::string(kMinimal) + "  tau: 0.7\n");
  EXPECT_NE(m.find("t.yaml:9: key 'tau' is given twice"), std::string::npos) << m;
  EXPECT_NE(message_of(std::string(kMinimal) + "name: u\n").find("'name' is given twice"),
            std::string::npos);
}

}  // namespace
}  // namespace lbdem
