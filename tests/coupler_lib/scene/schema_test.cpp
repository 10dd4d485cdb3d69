#include "coupler_lib/scene/schema.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <set>
#include <stdexcept>

#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {
namespace {

// Every key of the scene with the path of its mapping, each mapping once.
void for_each_key(const std::function<void(const MappingSchema&, const KeySchema&)>& f) {
  std::set<const MappingSchema*> seen;
  std::function<void(const MappingSchema&)> walk = [&](const MappingSchema& m) {
    if (!seen.insert(&m).second) return;
    auto keys = [&](const std::vector<KeySchema>& ks) {
      for (const auto& k : ks) {
        f(m, k);
        if (k.mapping) walk(*k.mapping);
      }
    };
    keys(m.keys);
    for (const auto& a : m.alternatives) keys(a.keys);
  };
  walk(scene_schema());
}

TEST(SceneSchema, EveryDefaultLiesWithinItsOwnRules) {
  int checked = 0;
  for_each_key([&](const MappingSchema& m, const KeySchema& k) {
    SCOPED_TRACE(m.path + "." + k.name);
    EXPECT_FALSE(k.meaning.empty());
    if (k.need == Need::derived || k.need == Need::optional) {
      EXPECT_FALSE(k.derived.empty());
    }
    if (k.need != Need::defaulted) return;
    ++checked;
    if (const auto* d = std::get_if<double>(&k.fallback)) {
      EXPECT_TRUE(k.bounds.contains(*d));
    }
    if (const auto* i = std::get_if<long long>(&k.fallback)) {
      EXPECT_TRUE(k.bounds.contains(static_cast<double>(*i)));
    }
    if (const auto* v = std::get_if<std::vector<double>>(&k.fallback)) {
      EXPECT_EQ(static_cast<int>(v->size()), k.size);
      for (double x : *v) EXPECT_TRUE(k.bounds.contains(x));
    }
    if (k.type == KeyType::choice) {
      const auto& w = std::get<std::string>(k.fallback);
      EXPECT_NE(std::find(k.values.begin(), k.values.end(), w), k.values.end());
    }
  });
  EXPECT_GT(checked, 60);
}

TEST(SceneSchema, GroupsAndAlternativesNameDeclaredKeys) {
  std::set<const MappingSchema*> seen;
  for_each_key([&](const MappingSchema& m, const KeySchema&) {
    if (!seen.insert(&m).second) return;
    auto declared = [&](const std::string& name, const Alternative* a) {
      for (const auto& k : m.keys)
        if (k.name == name) return true;
      for (const auto& alt : m.alternatives)
        if (!a || &alt == a)
          for (const auto& k : alt.keys)
            if (k.name == name) return true;
      return false;
    };
    for (const auto& g : m.exactly_one_of)
      for (const auto& n : g) EXPECT_TRUE(declared(n, nullptr)) << m.path << ": " << n;
    for (const auto& g : m.at_least_one_of)
      for (const auto& n : g) EXPECT_TRUE(declared(n, nullptr)) << m.path << ": " << n;
    for (const auto& a : m.alternatives) {
      if (!a.key.empty()) {
        EXPECT_TRUE(declared(a.key, &a)) << m.path << ": " << a.key;
      }
      for (const auto& g : a.exactly_one_of)
        for (const auto& n : g) EXPECT_TRUE(declared(n, &a)) << m.path << ": " << n;
    }
  });
}

TEST(SceneSchema, JsonListsEachMappingOnceFromTheTop) {
  const std::string json = scene_schema_json();
  EXPECT_EQ(json.rfind("{\n  \"format\": \"lbdem-scene-schema\",\n  \"version\": 1,", 0), 0u);
  EXPECT_NE(json.find("\"path\": \"shapes[]\""), std::string::npos);
  EXPECT_EQ(json.find("\"path\": \"shapes[]\""), json.rfind("\"path\": \"shapes[]\""));
  // Every kind's own key is there, not only the kinds some scene happens to use.
  for (const char* k : {"\"diameter\"", "\"edge\"", "\"edges\"", "\"semi_axes\"", "\"velocity\""})
    EXPECT_NE(json.find(k), std::string::npos) << k;
}

// The readers can read a key only as the schema declares it.
const MappingSchema& tiny_schema() {
  static const MappingSchema m{
      "",
      "test",
      {key::number("x", "a number").or_default(1.5).within(Bounds::positive()),
       key::choice("kind", {"a", "b"}, "kind").required()},
      {{"kind", "a", {key::integer("only_a", "a's key").or_default(3)}}}};
  return m;
}

TEST(SceneSchema, ReadersReadOnlyDeclaredKeysAsDeclared) {
  Section s = Section::load_string("kind: a\n", "t.yaml", tiny_schema());
  EXPECT_DOUBLE_EQ(s.get<double>("x"), 1.5);
  EXPECT_EQ(s.require_choice("kind"), "a");
  EXPECT_EQ(s.get<int>("only_a"), 3);
  EXPECT_THROW(s.get<double>("undeclared"), std::logic_error);
  EXPECT_THROW(s.get<int>("x"), std::logic_error);          // declared a number
  EXPECT_THROW(s.get<double>("x", 2.0), std::logic_error);  // not a derived default
  Section b = Section::load_string("kind: b\n", "t.yaml", tiny_schema());
  EXPECT_THROW(b.get<int>("only_a"), std::logic_error);  // a key of the other alternative
}

TEST(SceneSchema, AKeyTheSchemaAllowsButTheReaderSkipsIsABug) {
  Section s = Section::load_string("kind: a\nx: 2\n", "t.yaml", tiny_schema());
  s.require_choice("kind");
  EXPECT_THROW(s.finish(), std::logic_error);
  Section u = Section::load_string("kind: a\nz: 2\n", "t.yaml", tiny_schema());
  u.require_choice("kind");
  EXPECT_THROW(u.finish(), SceneError);  // unknown to the schema: the scene's mistake
}

TEST(SceneSchema, DefaultsOfTheWrongTypeAreRefused) {
  EXPECT_THROW(key::integer("n", "count").or_default(0.5), std::logic_error);
  EXPECT_THROW(key::choice("c", {"a"}, "choice").or_default("z"), std::logic_error);
}

}  // namespace
}  // namespace lbdem
