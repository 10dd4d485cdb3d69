#include <gtest/gtest.h>

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

TEST(Scene, WrongTypeAndMissingKey) {
  std::string text = kMinimal;
  text.replace(text.find("dx: 0.125"), 9, "dx: fine");
  EXPECT_THROW(parse(text), SceneError);
  EXPECT_THROW(parse("time: {end: 1}\nfluid: {domain: [1,1,1], viscosity: 1}\n"), SceneError);
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
