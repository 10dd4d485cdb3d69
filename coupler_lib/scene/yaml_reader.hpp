#pragma once
// Typed, documented access to one mapping of the scene YAML.
//
// Every key a section reads is declared in the scene schema (schema.hpp) with its type,
// default, admissible range, allowed values and a one-line meaning; a Section reads a key only
// through that declaration (reading an undeclared key, or reading it as another type, is a
// std::logic_error: a bug of the reader, caught by the tests that read the scenes). The reader
// records what it resolved so `--check` can print the complete effective scene. Unknown keys,
// wrong types, missing required keys and out-of-range values throw SceneError naming file,
// line, key and what was expected.
#include <yaml-cpp/yaml.h>

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/scene/schema.hpp"

namespace lbdem {

// One resolved key, as `--check` prints it: `value` for people, `json` (the typed value in
// full precision) for `--check --json`.
struct ResolvedKey {
  std::string path;
  std::string value;
  bool defaulted = false;
  std::string doc;
  std::string json;
};

// State shared by all sections read from one file.
struct SceneSource {
  std::string file;
  std::vector<ResolvedKey> resolved;
};

class Section {
 public:
  Section(YAML::Node node, std::shared_ptr<SceneSource> source, std::string path,
          const MappingSchema& schema);

  // Parse a whole file; throws SceneError on syntax errors.
  static Section load_file(const std::string& file, const MappingSchema& schema = scene_schema());
  static Section load_string(const std::string& text, const std::string& name,
                             const MappingSchema& schema = scene_schema());

  bool has(std::string_view key) const;
  const std::string& path() const { return path_; }
  const std::string& file() const { return source_->file; }
  std::shared_ptr<SceneSource> source() const { return source_; }
  const MappingSchema& schema() const { return *schema_; }

  // Scalars. `get` uses the schema's default when the key is absent (a defaulted key), or
  // `fallback` (a key whose default the reader derives from other keys); `require` throws when
  // the key is absent. `tighter` replaces the schema's bounds where the reader knows more (a
  // plane inside the domain).
  template <class T>
  T get(std::string_view key);
  template <class T>
  T get(std::string_view key, T fallback);
  template <class T>
  T require(std::string_view key);
  template <class T>
  T require(std::string_view key, Bounds tighter);

  // A word from the key's allowed values.
  std::string choice(std::string_view key);
  std::string choice(std::string_view key, std::string fallback);
  std::string require_choice(std::string_view key);

  // Fixed-size numeric vectors, e.g. `size: [1.0, 1.0, 2.0]`.
  std::array<double, 3> vec3(std::string_view key);
  std::array<double, 3> require_vec3(std::string_view key);
  // A vector of the key's size; a single number is read as a list of one.
  std::vector<double> numbers(std::string_view key);

  // Nested mappings and lists of mappings, each read against the key's mapping schema.
  Section section(std::string_view key);
  std::optional<Section> optional_section(std::string_view key);
  // The mapping at `key`, or an empty one when the key is absent: for sections whose absence
  // means "all defaults", so that their keys are read, and recorded, with their defaults.
  Section section_or_defaults(std::string_view key);
  std::vector<Section> list(std::string_view key);

  // Reject keys that were not declared by any read above (with a did-you-mean).
  void finish() const;

  // An error located at this section (or at one of its keys).
  [[noreturn]] void fail(std::string_view key, const std::string& what) const;
  std::string where(std::string_view key) const;

  const YAML::Node& node() const { return node_; }

 private:
  YAML::Node child(std::string_view key) const;
  std::string key_path(std::string_view key) const;
  // The schema entry of `key` (common or of this mapping's alternative), checked against the
  // way the reader reads it; declares the key as known.
  const KeySchema& spec(std::string_view key, const char* read_as);
  // A required key is absent; names a given key that looks like a misspelling of it.
  [[noreturn]] void fail_missing(std::string_view key, const std::string& expected) const;
  void record(std::string_view key, const std::string& value, bool defaulted, std::string_view doc,
              std::string json);
  template <class T>
  T convert(std::string_view key, const YAML::Node& n, const Bounds& b) const;
  template <class T>
  T read_scalar(std::string_view key, const KeySchema& k, const Bounds& b);
  std::string read_choice(std::string_view key, const KeySchema& k);
  std::array<double, 3> read_vec3(std::string_view key, const KeySchema& k);
  Section child_section(std::string_view key, const KeySchema& k, YAML::Node n) const;

  YAML::Node node_;
  std::shared_ptr<SceneSource> source_;
  std::string path_;
  const MappingSchema* schema_;
  const Alternative* alternative_ = nullptr;  // the variant this mapping is, if it has any
  std::set<std::string, std::less<>> declared_;
};

// A path given in a scene, resolved against the folder of the scene file when relative.
std::string resolve_scene_path(const std::string& scene_file, const std::string& path);

// Closest word by edit distance, empty if nothing is close enough to suggest.
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace lbdem
