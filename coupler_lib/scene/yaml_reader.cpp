#include "coupler_lib/scene/yaml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "coupler_lib/scene/json_text.hpp"

namespace lbdem {

Section::Section(YAML::Node node, std::shared_ptr<SceneSource> source, std::string path,
                 const MappingSchema& schema)
    : node_(std::move(node)), source_(std::move(source)), path_(std::move(path)), schema_(&schema) {
  // The first alternative that applies: its discriminating key has its word, or is given, or
  // (no key) none applied before it.
  for (const Alternative& a : schema_->alternatives) {
    const YAML::Node n = a.key.empty() ? YAML::Node() : node_[a.key];
    const bool applies = a.key.empty()     ? true
                         : a.value.empty() ? bool(n)
                                           : (n && n.IsScalar() && n.Scalar() == a.value);
    if (applies) {
      alternative_ = &a;
      break;
    }
  }
}

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

Section Section::load_file(const std::string& file, const MappingSchema& schema) {
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
  return Section(root, src, "", schema);
}

Section Section::load_string(const std::string& text, const std::string& name,
                             const MappingSchema& schema) {
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
  return Section(root, src, "", schema);
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

const KeySchema& Section::spec(std::string_view key, const char* read_as) {
  const KeySchema* found = nullptr;
  for (const auto& k : schema_->keys)
    if (k.name == key) found = &k;
  if (!found && alternative_)
    for (const auto& k : alternative_->keys)
      if (k.name == key) found = &k;
  if (!found)
    throw std::logic_error(
        "scene schema: the reader reads '" + key_path(key) + "', which the schema of '" +
        schema_->path + "' does not declare" +
        (alternative_ ? " (alternative " + alternative_->key + "=" + alternative_->value + ")"
                      : std::string()));
  const std::string as(read_as);
  const KeyType t = found->type;
  const bool fits = as == key_type_name(t) ||
                    (as == "section" && t == KeyType::choice && found->mapping) ||
                    (as == "vec3" && t == KeyType::vector && found->size == 3) ||
                    (as == "numbers" && t == KeyType::vector);
  if (!fits)
    throw std::logic_error("scene schema: the reader reads '" + key_path(key) + "' as " + as +
                           ", the schema declares a " + key_type_name(t));
  declared_.emplace(key);
  return *found;
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
T Section::convert(std::string_view key, const YAML::Node& n, const Bounds& b) const {
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

namespace {
template <class T>
const char* schema_type() {
  if constexpr (std::is_same_v<T, bool>)
    return "boolean";
  else if constexpr (std::is_integral_v<T>)
    return "integer";
  else if constexpr (std::is_floating_point_v<T>)
    return "number";
  else
    return "string";
}
template <class T>
T typed_default(const KeySchema& k) {
  if constexpr (std::is_same_v<T, bool>)
    return std::get<bool>(k.fallback);
  else if constexpr (std::is_integral_v<T>)
    return static_cast<T>(std::get<long long>(k.fallback));
  else if constexpr (std::is_floating_point_v<T>)
    return std::get<double>(k.fallback);
  else
    return std::get<std::string>(k.fallback);
}
void expect_need(const std::string& path, const KeySchema& k, bool derived) {
  const bool ok =
      derived ? (k.need == Need::derived || k.need == Need::optional) : k.need == Need::defaulted;
  if (!ok)
    throw std::logic_error("scene schema: '" + path + "' is read with " +
                           (derived ? "a derived default" : "the schema's default") +
                           " but declared " + need_name(k.need));
}
}  // namespace

template <class T>
T Section::read_scalar(std::string_view key, const KeySchema& k, const Bounds& b) {
  const YAML::Node n = child(key);
  if (!n) fail_missing(key, "(" + k.meaning + ")");
  T v = convert<T>(key, n, b);
  record(key, to_text(v), false, k.meaning, to_json(v));
  return v;
}

template <class T>
T Section::get(std::string_view key) {
  const KeySchema& k = spec(key, schema_type<T>());
  expect_need(key_path(key), k, false);
  if (!has(key)) {
    const T fallback = typed_default<T>(k);
    record(key, to_text(fallback), true, k.meaning, to_json(fallback));
    return fallback;
  }
  return read_scalar<T>(key, k, k.bounds);
}

template <class T>
T Section::get(std::string_view key, T fallback) {
  const KeySchema& k = spec(key, schema_type<T>());
  expect_need(key_path(key), k, true);
  if (!has(key)) {
    record(key, to_text(fallback), true, k.meaning, to_json(fallback));
    return fallback;
  }
  return read_scalar<T>(key, k, k.bounds);
}

template <class T>
T Section::require(std::string_view key) {
  const KeySchema& k = spec(key, schema_type<T>());
  return read_scalar<T>(key, k, k.bounds);
}

template <class T>
T Section::require(std::string_view key, Bounds tighter) {
  const KeySchema& k = spec(key, schema_type<T>());
  return read_scalar<T>(key, k, tighter);
}

template double Section::get<double>(std::string_view);
template int Section::get<int>(std::string_view);
template long Section::get<long>(std::string_view);
template long long Section::get<long long>(std::string_view);
template bool Section::get<bool>(std::string_view);
template std::string Section::get<std::string>(std::string_view);
template double Section::get<double>(std::string_view, double);
template bool Section::get<bool>(std::string_view, bool);
template double Section::require<double>(std::string_view);
template int Section::require<int>(std::string_view);
template long Section::require<long>(std::string_view);
template std::string Section::require<std::string>(std::string_view);
template double Section::require<double>(std::string_view, Bounds);

namespace {
std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + v[i];
  return s;
}
}  // namespace

std::string Section::read_choice(std::string_view key, const KeySchema& k) {
  const YAML::Node n = child(key);
  auto v = convert<std::string>(key, n, {});
  if (std::find(k.values.begin(), k.values.end(), v) == k.values.end()) {
    std::string hint = did_you_mean(v, k.values);
    fail(key, "expected one of {" + join(k.values) + "}, got '" + v + "'" +
                  (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  record(key, v, false, k.meaning, json_string(v));
  return v;
}

std::string Section::choice(std::string_view key) {
  const KeySchema& k = spec(key, "choice");
  expect_need(key_path(key), k, false);
  if (!has(key)) {
    const std::string fallback = std::get<std::string>(k.fallback);
    record(key, fallback, true, k.meaning, json_string(fallback));
    return fallback;
  }
  return read_choice(key, k);
}

std::string Section::choice(std::string_view key, std::string fallback) {
  const KeySchema& k = spec(key, "choice");
  expect_need(key_path(key), k, true);
  if (!has(key)) {
    record(key, fallback, true, k.meaning, json_string(fallback));
    return fallback;
  }
  return read_choice(key, k);
}

std::string Section::require_choice(std::string_view key) {
  const KeySchema& k = spec(key, "choice");
  if (!has(key)) fail_missing(key, "(one of {" + join(k.values) + "})");
  return read_choice(key, k);
}

std::vector<double> Section::numbers(std::string_view key) {
  const KeySchema& k = spec(key, "numbers");
  const YAML::Node n = child(key);
  if (!n) fail_missing(key, "(" + k.meaning + ")");
  std::vector<double> out;
  if (n.IsScalar()) {
    out.push_back(convert<double>(key, n, k.bounds));
  } else if (n.IsSequence()) {
    for (const auto& e : n) out.push_back(convert<double>(key, e, k.bounds));
  } else {
    fail(key, "expected a list of numbers");
  }
  std::string txt = "[";
  for (size_t i = 0; i < out.size(); ++i) txt += (i ? ", " : "") + to_text(out[i]);
  record(key, txt + "]", false, k.meaning, json_list(out));
  return out;
}

std::array<double, 3> Section::read_vec3(std::string_view key, const KeySchema& k) {
  const YAML::Node n = child(key);
  if (!n) fail_missing(key, "(" + k.meaning + ")");
  if (!n.IsSequence() || n.size() != 3) fail(key, "expected a list of 3 numbers, e.g. [0, 0, 1]");
  std::array<double, 3> v{};
  for (int i = 0; i < 3; ++i) v[i] = convert<double>(key, n[i], k.bounds);
  record(key, "[" + to_text(v[0]) + ", " + to_text(v[1]) + ", " + to_text(v[2]) + "]", false,
         k.meaning, json_list(v));
  return v;
}

std::array<double, 3> Section::require_vec3(std::string_view key) {
  return read_vec3(key, spec(key, "vec3"));
}

std::array<double, 3> Section::vec3(std::string_view key) {
  const KeySchema& k = spec(key, "vec3");
  expect_need(key_path(key), k, false);
  if (!has(key)) {
    const auto& d = std::get<std::vector<double>>(k.fallback);
    const std::array<double, 3> fallback{d[0], d[1], d[2]};
    record(key,
           "[" + to_text(fallback[0]) + ", " + to_text(fallback[1]) + ", " + to_text(fallback[2]) +
               "]",
           true, k.meaning, json_list(fallback));
    return fallback;
  }
  return read_vec3(key, k);
}

Section Section::child_section(std::string_view key, const KeySchema& k, YAML::Node n) const {
  return Section(std::move(n), source_, key_path(key), *k.mapping);
}

Section Section::section(std::string_view key) {
  auto s = optional_section(key);
  if (!s) {
    const KeySchema& k = spec(key, "section");
    fail("", "missing required section '" + std::string(key) + "' (" + k.meaning + ")");
  }
  return *s;
}

std::optional<Section> Section::optional_section(std::string_view key) {
  const KeySchema& k = spec(key, "section");
  const YAML::Node n = child(key);
  if (!n) return std::nullopt;
  if (!n.IsMap()) fail(key, "expected a mapping (" + k.meaning + ")");
  return child_section(key, k, n);
}

Section Section::section_or_defaults(std::string_view key) {
  if (auto s = optional_section(key)) return *s;
  return child_section(key, spec(key, "section"), YAML::Node(YAML::NodeType::Map));
}

std::vector<Section> Section::list(std::string_view key) {
  const KeySchema& k = spec(key, "list");
  std::vector<Section> out;
  const YAML::Node n = child(key);
  if (!n) return out;
  if (!n.IsSequence()) fail(key, "expected a list (" + k.meaning + ")");
  for (size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsMap()) fail(key, "entry " + std::to_string(i) + ": expected a mapping");
    out.emplace_back(n[i], source_, key_path(key) + "[" + std::to_string(i) + "]", *k.mapping);
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
    // A key the schema allows here but the reader left unread would be refused as unknown while
    // --schema and the JSON Schema accept it: a bug of the reader, not of the scene.
    auto in = [&](const std::vector<KeySchema>& ks) {
      return std::any_of(ks.begin(), ks.end(), [&](const KeySchema& k) { return k.name == key; });
    };
    if (in(schema_->keys) || (alternative_ && in(alternative_->keys)))
      throw std::logic_error("scene schema: '" + key_path(key) +
                             "' is declared in the schema but its reader did not read it");
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
