#pragma once
// The scene's schema as data: every key of every section, with its type, unit, default,
// bounds, allowed values and meaning. The section readers (yaml_reader.hpp) can read a key only
// through its entry here, taking its default, bounds, allowed values and meaning from it, so the
// readers, `--schema` (both programs print scene_schema_json()), docs/scene-reference.md and
// docs/scene.schema.json (generated from `--schema` by tools/scene_schema.py) cannot drift apart.
//
// Each section file declares the schema of its mappings next to the reader that uses it, e.g.
//   const MappingSchema& coupling_schema() {
//     static const MappingSchema m{"coupling", "fluid-DEM packet exchange",
//       {key::number("margin", "stencil margin in fluid cells").or_default(2.0)
//            .within(Bounds::non_negative()), ...}};
//     return m;
//   }
#include <array>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace lbdem {

// Inclusive/exclusive numeric bounds for a scalar key.
struct Bounds {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  static Bounds positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Bounds non_negative() {
    return {0.0, std::numeric_limits<double>::infinity(), false, false};
  }
  static Bounds at_least(double v) {
    return {v, std::numeric_limits<double>::infinity(), false, false};
  }
  static Bounds above(double v) {
    return {v, std::numeric_limits<double>::infinity(), true, false};
  }
  static Bounds closed(double a, double b) { return {a, b, false, false}; }
  bool contains(double v) const;
  bool unbounded() const;
  std::string describe() const;
};

// What a key's value is. `choice` is a word from `values`; `vector` a list of `size` numbers;
// `section` a mapping and `list` a list of mappings, both described by `mapping`. A choice that
// also has a `mapping` may be written either as the word or as that mapping.
enum class KeyType { number, integer, boolean, string, choice, vector, section, list };

// Whether a key may be left out, and what then holds.
//   required:  must be given
//   defaulted: the code default `fallback` holds
//   derived:   the reader derives the value from other keys (`derived` says how)
//   optional:  absence has its own meaning (`derived` says which), or the key belongs to a group
//              of which exactly one is given
enum class Need { required, defaulted, derived, optional };

struct MappingSchema;

struct KeySchema {
  using Value =
      std::variant<std::monostate, bool, long long, double, std::string, std::vector<double>>;
  std::string name;
  KeyType type = KeyType::number;
  std::string meaning;
  std::string unit;  // SI unit of a number or vector ("m", "Pa s"); empty: dimensionless or none
  Need need = Need::optional;
  Value fallback;       // defaulted: the code default
  std::string derived;  // derived or optional: the default's rule, or what absence means
  Bounds bounds;        // numbers, integers and vector components
  std::vector<std::string> values;         // choice: the allowed words
  int size = 0;                            // vector: number of components
  const MappingSchema* mapping = nullptr;  // section, list entry; a choice's mapping form

  // Builders, chained on the key:: factories below.
  KeySchema required() const;
  KeySchema or_default(double v) const;
  KeySchema or_default(int v) const;
  KeySchema or_default(bool v) const;
  KeySchema or_default(const char* v) const;
  KeySchema or_default(std::array<double, 3> v) const;
  KeySchema derived_as(std::string rule) const;
  KeySchema absent_means(std::string meaning) const;
  KeySchema within(Bounds b) const;
  KeySchema in(std::string unit) const;

  // The default's JSON text ("null" unless defaulted).
  std::string fallback_json() const;
};

namespace key {
KeySchema number(std::string name, std::string meaning);
KeySchema integer(std::string name, std::string meaning);
KeySchema boolean(std::string name, std::string meaning);
KeySchema text(std::string name, std::string meaning);
KeySchema choice(std::string name, std::vector<std::string> values, std::string meaning);
KeySchema vector(std::string name, int size, std::string meaning);
KeySchema vec3(std::string name, std::string meaning);
KeySchema section(std::string name, const MappingSchema& mapping, std::string meaning);
KeySchema list(std::string name, const MappingSchema& entry, std::string meaning);
}  // namespace key

// A variant of a mapping: keys allowed only when `key` has the word `value`, or (value empty)
// when `key` is given at all, or (key empty) when no other alternative applies. The first
// alternative that applies is the one a mapping has.
struct Alternative {
  Alternative(std::string key_, std::string value_, std::vector<KeySchema> keys_,
              std::vector<std::vector<std::string>> exactly_one_of_ = {})
      : key(std::move(key_)),
        value(std::move(value_)),
        keys(std::move(keys_)),
        exactly_one_of(std::move(exactly_one_of_)) {}
  std::string key;
  std::string value;
  std::vector<KeySchema> keys;
  std::vector<std::vector<std::string>> exactly_one_of;
};

struct MappingSchema {
  using Groups = std::vector<std::vector<std::string>>;
  MappingSchema(std::string path_, std::string meaning_, std::vector<KeySchema> keys_,
                std::vector<Alternative> alternatives_ = {}, Groups exactly_one_of_ = {},
                Groups at_least_one_of_ = {})
      : path(std::move(path_)),
        meaning(std::move(meaning_)),
        keys(std::move(keys_)),
        alternatives(std::move(alternatives_)),
        exactly_one_of(std::move(exactly_one_of_)),
        at_least_one_of(std::move(at_least_one_of_)) {}
  // Where the mapping sits in a scene, as the reference names it ("fluid.boundaries.<face>",
  // "shapes[]"); also its id in `--schema`, where each mapping is listed once.
  std::string path;
  std::string meaning;
  std::vector<KeySchema> keys;  // keys of every variant
  std::vector<Alternative> alternatives;
  // Groups of keys of which exactly one must be given (e.g. fluid.dx or fluid.resolution).
  std::vector<std::vector<std::string>> exactly_one_of;
  // Groups of which at least one must be given.
  std::vector<std::vector<std::string>> at_least_one_of;
};

// The whole scene file (coupler_lib/scene/scene.cpp).
const MappingSchema& scene_schema();

// The schema as JSON: what `fluid_app --schema` and `dem_app --schema` print.
//   {"format": "lbdem-scene-schema", "version": 1, "root": "",
//    "mappings": [MAPPING, ...]}           each mapping once, in the order a scene is read
//   MAPPING = {"path", "meaning", "keys": [KEY], "alternatives": [{"key", "value", "keys",
//              "exactly_one_of"}], "exactly_one_of": [[names]], "at_least_one_of": [[names]]}
//   KEY = {"name", "type", "need", "default" (defaulted) | "rule" (derived, optional), "unit",
//          "minimum" | "exclusive_minimum", "maximum" | "exclusive_maximum", "values", "size",
//          "mapping": the path of its MAPPING, "meaning"}
std::string scene_schema_json();

const char* key_type_name(KeyType t);
const char* need_name(Need n);

}  // namespace lbdem
