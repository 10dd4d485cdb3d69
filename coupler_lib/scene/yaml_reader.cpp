#include "coupler_lib/scene/yaml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>

#include "coupler_lib/scene/json_text.hpp"

namespace lbdem {

bool Bounds::contains(double v) const {
  if (std::isnan(v)) return false;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string Bounds::describe() const {
  std::ostringstream s;
  const bool has_lo = std::isfinite(lo);
  const bool has_hi = std::isfinite(hi);
  if (has_lo && has_hi) {
    s << "in " << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
  } else if (has_lo) {
    s << (lo_open ? "> " : ">= ") << lo;
  } else if (has_hi) {
    s << (hi_open ? "< " : "<= ") << hi;
  } else {
    s << "finite";
  }
  return s.str();
}

Section::Section(YAML::Node node, std::shared_ptr<SceneSource> source, std::string path)
    : node_(std::move(node)), source_(std::move(source)), path_(std::move(path)) {}

namespace {

// yaml-cpp keeps both entries of a key given twice and `node[key]` silently returns the first;
// YAML 1.2 requires keys to be unique, so a repeated key is refused wherever it occurs.
void reject_duplicate_keys(const YAML::Node& n, const std::string& file) {
  if (n.IsSequence()) {
    for (const auto& e : n) reject_duplicate_keys(e, file);
    return;
  }
  if (!n.IsMap()) return;
  std::set<std::string> seen;
  for (const auto& kv : n) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : YAML::Dump(kv.first);
    if (!seen.insert(key).second)
      throw SceneError(file + ":" + std::to_string(kv.first.Mark().line + 1) + ": key '" + key +
                       "' is given twice in the same mapping (YAML keys must be unique)");
    reject_duplicate_keys(kv.second, file);
  }
}

}  // namespace

Section Section::load_file(const std::string& file) {
  auto src = std::make_shared<SceneSource>();
  src->file = file;
  YAML::Node root;
  try {
    root = YAML::LoadFile(file);
  } catch (const YAML::BadFile&) {
    throw SceneError(file + ": cannot open the scene file");
  } catch (const YAML::ParserException& e) {
    throw SceneError(file + ":" + std::to_string(e.mark.line + 1) + ":" +
                     std::to_string(e.mark.column + 1) + ": YAML syntax error: " + e.msg);
  }
  if (!root.IsMap()) throw SceneError(file + ": the scene must be a YAML mapping of sections");
  reject_duplicate_keys(root, file);
  return Section(root, src, "");
}

Section Section::load_string(const std::string& text, const std::string& name) {
  auto src = std::make_shared<SceneSource>();
  src->file = name;
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw SceneError(name + ":" + std::to_string(e.mark.line + 1) +
                     ": YAML syntax error: " + e.msg);
  }
  if (!root.IsMap()) throw SceneError(name + ": the scene must be a YAML mapping of sections");
  reject_duplicate_keys(root, name);
  return Section(root, src, "");
}

bool Section::has(std::string_view key) const {
  return bool(node_[std::string(key)]);
}

YAML::Node Section::child(std::string_view key) const {
  return node_[std::string(key)];
}

std::string Section::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

std::string Section::where(std::string_view key) const {
  YAML::Mark m = node_.Mark();
  if (!key.empty()) {
    if (auto c = child(key); c) m = c.Mark();
  }
  std::string loc = source_->file;
  if (!m.is_null()) loc += ":" + std::to_string(m.line + 1);
  return loc + ": " +
         (key.empty() ? (path_.empty() ? std::string("<top>") : path_) : key_path(key));
}

void Section::fail(std::string_view key, const std::string& what) const {
  throw SceneError(where(key) + ": " + what);
}

void Section::declare(std::string_view key) {
  declared_.emplace(key);
}

void Section::record(std::string_view key, const std::string& value, bool defaulted,
                     std::string_view doc, std::string json) {
  source_->resolved.push_back({key_path(key), value, defaulted, std::string(doc), std::move(json)});
}

namespace {
std::string scalar_text(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  std::ostringstream s;
  s << YAML::Dump(n);
  return s.str();
}
template <class T>
constexpr const char* type_name() {
  if constexpr (std::is_same_v<T, bool>)
    return "true or false";
  else if constexpr (std::is_integral_v<T>)
    return "an integer";
  else if constexpr (std::is_floating_point_v<T>)
    return "a number";
  else
    return "a string";
}
template <class T>
std::string to_text(const T& v) {
  if constexpr (std::is_same_v<T, bool>)
    return v ? "true" : "false";
  else if constexpr (std::is_same_v<T, std::string>)
    return v;
  else {
    std::ostringstream s;
    s << v;
    return s.str();
  }
}
template <class T>
std::string to_json(const T& v) {
  if constexpr (std::is_same_v<T, bool>)
    return v ? "true" : "false";
  else if constexpr (std::is_same_v<T, std::string>)
    return json_string(v);
  else if constexpr (std::is_integral_v<T>)
    return std::to_string(v);
  else
    return json_number(v);
}
}  // namespace

template <class T>
T Section::convert(std::string_view key, const YAML::Node& n, Bounds b) const {
  if (!n.IsScalar())
    fail(key, std::string("expected ") + type_name<T>() + ", got a " +
                  (n.IsSequence() ? "list" : "mapping"));
  T v{};
  try {
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
      const double d = n.as<double>();
      if (!std::isfinite(d) || d != std::floor(d) ||
          std::fabs(d) > double(std::numeric_limits<T>::max()))
        throw YAML::BadConversion(n.Mark());
      v = static_cast<T>(d);
    } else {
      v = n.as<T>();
    }
  } catch (const YAML::BadConversion&) {
    fail(key, std::string("expected ") + type_name<T>() + ", got '" + scalar_text(n) + "'");
  }
  if constexpr (std::is_floating_point_v<T>) {
    // .inf and .nan are valid YAML numbers but never a valid physical input.
    if (!std::isfinite(v)) fail(key, "expected a finite number, got '" + scalar_text(n) + "'");
  }
  if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
    if (!b.contains(static_cast<double>(v)))
      fail(key, "expected a value " + b.describe() + ", got " + to_text(v));
  }
  return v;
}

template <class T>
T Section::get(std::string_view key, T fallback, std::string_view doc, Bounds b) {
  declare(key);
  const YAML::Node n = child(key);
  if (!n) {
    record(key, to_text(fallback), true, doc, to_json(fallback));
    return fallback;
  }
  T v = convert<T>(key, n, b);
  record(key, to_text(v), false, doc, to_json(v));
  return v;
}

template <class T>
T Section::require(std::string_view key, std::string_view doc, Bounds b) {
  declare(key);
  const YAML::Node n = child(key);
  if (!n) fail_missing(key, "(" + std::string(doc) + ")");
  T v = convert<T>(key, n, b);
  record(key, to_text(v), false, doc, to_json(v));
  return v;
}

template double Section::get<double>(std::string_view, double, std::string_view, Bounds);
template int Section::get<int>(std::string_view, int, std::string_view, Bounds);
template long Section::get<long>(std::string_view, long, std::string_view, Bounds);
template long long Section::get<long long>(std::string_view, long long, std::string_view, Bounds);
template unsigned Section::get<unsigned>(std::string_view, unsigned, std::string_view, Bounds);
template bool Section::get<bool>(std::string_view, bool, std::string_view, Bounds);
template std::string Section::get<std::string>(std::string_view, std::string, std::string_view,
                                               Bounds);
template double Section::require<double>(std::string_view, std::string_view, Bounds);
template int Section::require<int>(std::string_view, std::string_view, Bounds);
template long Section::require<long>(std::string_view, std::string_view, Bounds);
template long long Section::require<long long>(std::string_view, std::string_view, Bounds);
template bool Section::require<bool>(std::string_view, std::string_view, Bounds);
template std::string Section::require<std::string>(std::string_view, std::string_view, Bounds);

namespace {
std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
  return s;
}
}  // namespace

std::string Section::choice(std::string_view key, std::string fallback,
                            const std::vector<std::string>& options, std::string_view doc) {
  declare(key);
  const YAML::Node n = child(key);
  if (!n) {
    record(key, fallback, true, doc, json_string(fallback));
    return fallback;
  }
  auto v = convert<std::string>(key, n, {});
  if (std::find(options.begin(), options.end(), v) == options.end()) {
    std::string hint = did_you_mean(v, options);
    fail(key, "expected one of {" + join(options) + "}, got '" + v + "'" +
                  (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  record(key, v, false, doc, json_string(v));
  return v;
}

std::string Section::require_choice(std::string_view key, const std::vector<std::string>& options,
                                    std::string_view doc) {
  if (!has(key)) fail_missing(key, "(one of {" + join(options) + "})");
  return choice(key, "", options, doc);
}

std::vector<double> Section::numbers(std::string_view key, std::string_view doc, Bounds b) {
  declare(key);
  const YAML::Node n = child(key);
  if (!n) fail_missing(key, "(" + std::string(doc) + ")");
  std::vector<double> out;
  if (n.IsScalar()) {
    out.push_back(convert<double>(key, n, b));
  } else if (n.IsSequence()) {
    for (const auto& e : n) out.push_back(convert<double>(key, e, b));
  } else {
    fail(key, "expected a list of numbers");
  }
  std::string txt = "[";
  for (size_t i = 0; i < out.size(); ++i) txt += (i ? ", " : "") + to_text(out[i]);
  record(key, txt + "]", false, doc, json_list(out));
  return out;
}

std::array<double, 3> Section::require_vec3(std::string_view key, std::string_view doc, Bounds b) {
  declare(key);
  const YAML::Node n = child(key);
  if (!n) fail_missing(key, "(" + std::string(doc) + ")");
  if (!n.IsSequence() || n.size() != 3) fail(key, "expected a list of 3 numbers, e.g. [0, 0, 1]");
  std::array<double, 3> v{};
  for (int i = 0; i < 3; ++i) v[i] = convert<double>(key, n[i], b);
  record(key, "[" + to_text(v[0]) + ", " + to_text(v[1]) + ", " + to_text(v[2]) + "]", false, doc,
         json_list(v));
  return v;
}

std::array<double, 3> Section::vec3(std::string_view key, std::array<double, 3> fallback,
                                    std::string_view doc, Bounds b) {
  if (!has(key)) {
    declare(key);
    record(key,
           "[" + to_text(fallback[0]) + ", " + to_text(fallback[1]) + ", " + to_text(fallback[2]) +
               "]",
           true, doc, json_list(fallback));
    return fallback;
  }
  return require_vec3(key, doc, b);
}

Section Section::section(std::string_view key, std::string_view doc) {
  auto s = optional_section(key, doc);
  if (!s)
    fail("", "missing required section '" + std::string(key) + "' (" + std::string(doc) + ")");
  return *s;
}

std::optional<Section> Section::optional_section(std::string_view key, std::string_view doc) {
  declare(key);
  const YAML::Node n = child(key);
  if (!n) return std::nullopt;
  if (!n.IsMap()) fail(key, "expected a mapping (" + std::string(doc) + ")");
  return Section(n, source_, key_path(key));
}

Section Section::section_or_defaults(std::string_view key, std::string_view doc) {
  if (auto s = optional_section(key, doc)) return *s;
  return Section(YAML::Node(YAML::NodeType::Map), source_, key_path(key));
}

std::vector<Section> Section::list(std::string_view key, std::string_view doc) {
  declare(key);
  std::vector<Section> out;
  const YAML::Node n = child(key);
  if (!n) return out;
  if (!n.IsSequence()) fail(key, "expected a list (" + std::string(doc) + ")");
  for (size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsMap()) fail(key, "entry " + std::to_string(i) + ": expected a mapping");
    out.emplace_back(n[i], source_, key_path(key) + "[" + std::to_string(i) + "]");
  }
  return out;
}

void Section::fail_missing(std::string_view key, const std::string& expected) const {
  std::string given;
  if (node_.IsMap())
    for (const auto& kv : node_) {
      const auto k = kv.first.as<std::string>();
      if (k != key && !did_you_mean(k, {std::string(key)}).empty()) given = k;
    }
  fail("", "missing required key '" + std::string(key) + "' " + expected +
               (given.empty() ? "" : "; '" + given + "' is given: a misspelling of it?"));
}

void Section::finish() const {
  if (!node_.IsMap()) return;
  std::vector<std::string> known(declared_.begin(), declared_.end());
  for (const auto& kv : node_) {
    const auto key = kv.first.as<std::string>();
    if (declared_.count(key)) continue;
    std::string hint = did_you_mean(key, known);
    std::string loc = source_->file;
    if (!kv.first.Mark().is_null()) loc += ":" + std::to_string(kv.first.Mark().line + 1);
    throw SceneError(loc + ": " + key_path(key) + ": unknown key" +
                     (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                     "; known keys here: " + join(known));
  }
}

std::string resolve_scene_path(const std::string& scene_file, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute()) return path;
  const std::filesystem::path resolved =
      (std::filesystem::path(scene_file).parent_path() / p).lexically_normal();
  return resolved.empty() ? std::string(".") : resolved.string();
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  auto distance = [](std::string_view a, std::string_view b) {
    std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
      cur[0] = i;
      for (size_t j = 1; j <= b.size(); ++j)
        cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
      std::swap(prev, cur);
    }
    return prev[b.size()];
  };
  std::string best;
  size_t best_d = std::max<size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    size_t d = distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  return best;
}

}  // namespace lbdem
