#pragma once
// Typed, documented access to one mapping of the scene YAML.
//
// Every key a section reads is declared at the point of reading, with its type, default,
// admissible range and a one-line description; the reader records what it resolved so
// `--check` can print the complete effective scene. Unknown keys, wrong types, missing
// required keys and out-of-range values throw SceneError naming file, line, key and what
// was expected.
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
  std::string describe() const;
};

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
  Section(YAML::Node node, std::shared_ptr<SceneSource> source, std::string path);

  // Parse a whole file; throws SceneError on syntax errors.
  static Section load_file(const std::string& file);
  static Section load_string(const std::string& text, const std::string& name);

  bool has(std::string_view key) const;
  const std::string& path() const { return path_; }
  const std::string& file() const { return source_->file; }
  std::shared_ptr<SceneSource> source() const { return source_; }

  // Scalars. `get` uses the default when the key is absent; `require` throws.
  template <class T>
  T get(std::string_view key, T fallback, std::string_view doc, Bounds b = {});
  template <class T>
  T require(std::string_view key, std::string_view doc, Bounds b = {});

  // A string restricted to a fixed set of words.
  std::string choice(std::string_view key, std::string fallback,
                     const std::vector<std::string>& options, std::string_view doc);
  std::string require_choice(std::string_view key, const std::vector<std::string>& options,
                             std::string_view doc);

  // Fixed-size numeric vectors, e.g. `size: [1.0, 1.0, 2.0]`.
  std::array<double, 3> vec3(std::string_view key, std::array<double, 3> fallback,
                             std::string_view doc, Bounds b = {});
  std::array<double, 3> require_vec3(std::string_view key, std::string_view doc, Bounds b = {});
  std::vector<double> numbers(std::string_view key, std::string_view doc, Bounds b = {});

  // Nested mappings and lists of mappings.
  Section section(std::string_view key, std::string_view doc);
  std::optional<Section> optional_section(std::string_view key, std::string_view doc);
  // The mapping at `key`, or an empty one when the key is absent: for sections whose absence
  // means "all defaults", so that their keys are read, and recorded, with their defaults.
  Section section_or_defaults(std::string_view key, std::string_view doc);
  std::vector<Section> list(std::string_view key, std::string_view doc);

  // Reject keys that were not declared by any read above (with a did-you-mean).
  void finish() const;

  // An error located at this section (or at one of its keys).
  [[noreturn]] void fail(std::string_view key, const std::string& what) const;
  std::string where(std::string_view key) const;

  const YAML::Node& node() const { return node_; }

 private:
  YAML::Node child(std::string_view key) const;
  std::string key_path(std::string_view key) const;
  void declare(std::string_view key);
  // A required key is absent; names a given key that looks like a misspelling of it.
  [[noreturn]] void fail_missing(std::string_view key, const std::string& expected) const;
  void record(std::string_view key, const std::string& value, bool defaulted, std::string_view doc,
              std::string json);
  template <class T>
  T convert(std::string_view key, const YAML::Node& n, Bounds b) const;

  YAML::Node node_;
  std::shared_ptr<SceneSource> source_;
  std::string path_;
  std::set<std::string, std::less<>> declared_;
};

// A path given in a scene, resolved against the folder of the scene file when relative.
std::string resolve_scene_path(const std::string& scene_file, const std::string& path);

// Closest word by edit distance, empty if nothing is close enough to suggest.
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace lbdem
