#include "coupler_lib/scene/schema.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "coupler_lib/scene/json_text.hpp"

namespace lbdem {

bool Bounds::contains(double v) const {
  if (std::isnan(v)) return false;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

bool Bounds::unbounded() const {
  return !std::isfinite(lo) && !std::isfinite(hi);
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

namespace {

KeySchema make(std::string name, KeyType type, std::string meaning) {
  KeySchema k;
  k.name = std::move(name);
  k.type = type;
  k.meaning = std::move(meaning);
  return k;
}

// A default of the wrong type is a bug of the schema: it would print one type and read another.
KeySchema with_default(KeySchema k, KeySchema::Value v, bool fits) {
  if (!fits)
    throw std::logic_error("scene schema: the default of '" + k.name + "' does not fit its type " +
                           key_type_name(k.type));
  k.need = Need::defaulted;
  k.fallback = std::move(v);
  return k;
}

}  // namespace

namespace key {
KeySchema number(std::string name, std::string meaning) {
  return make(std::move(name), KeyType::number, std::move(meaning));
}
KeySchema integer(std::string name, std::string meaning) {
  return make(std::move(name), KeyType::integer, std::move(meaning));
}
KeySchema boolean(std::string name, std::string meaning) {
  return make(std::move(name), KeyType::boolean, std::move(meaning));
}
KeySchema text(std::string name, std::string meaning) {
  return make(std::move(name), KeyType::string, std::move(meaning));
}
KeySchema choice(std::string name, std::vector<std::string> values, std::string meaning) {
  KeySchema k = make(std::move(name), KeyType::choice, std::move(meaning));
  k.values = std::move(values);
  return k;
}
KeySchema vector(std::string name, int size, std::string meaning) {
  KeySchema k = make(std::move(name), KeyType::vector, std::move(meaning));
  k.size = size;
  return k;
}
KeySchema vec3(std::string name, std::string meaning) {
  return vector(std::move(name), 3, std::move(meaning));
}
KeySchema section(std::string name, const MappingSchema& mapping, std::string meaning) {
  KeySchema k = make(std::move(name), KeyType::section, std::move(meaning));
  k.mapping = &mapping;
  return k;
}
KeySchema list(std::string name, const MappingSchema& entry, std::string meaning) {
  KeySchema k = make(std::move(name), KeyType::list, std::move(meaning));
  k.mapping = &entry;
  return k;
}
}  // namespace key

KeySchema KeySchema::required() const {
  KeySchema k = *this;
  k.need = Need::required;
  return k;
}

KeySchema KeySchema::or_default(double v) const {
  return with_default(*this, v, type == KeyType::number);
}

KeySchema KeySchema::or_default(int v) const {
  if (type == KeyType::number) return with_default(*this, static_cast<double>(v), true);
  return with_default(*this, static_cast<long long>(v), type == KeyType::integer);
}

KeySchema KeySchema::or_default(bool v) const {
  return with_default(*this, v, type == KeyType::boolean);
}

KeySchema KeySchema::or_default(const char* v) const {
  bool fits = type == KeyType::string;
  if (type == KeyType::choice)
    for (const auto& w : values) fits = fits || w == v;
  return with_default(*this, std::string(v), fits);
}

KeySchema KeySchema::or_default(std::array<double, 3> v) const {
  return with_default(*this, std::vector<double>(v.begin(), v.end()),
                      type == KeyType::vector && size == 3);
}

KeySchema KeySchema::derived_as(std::string rule) const {
  KeySchema k = *this;
  k.need = Need::derived;
  k.derived = std::move(rule);
  return k;
}

KeySchema KeySchema::absent_means(std::string meaning_if_absent) const {
  KeySchema k = *this;
  k.need = Need::optional;
  k.derived = std::move(meaning_if_absent);
  return k;
}

KeySchema KeySchema::within(Bounds b) const {
  KeySchema k = *this;
  k.bounds = b;
  return k;
}

KeySchema KeySchema::in(std::string u) const {
  KeySchema k = *this;
  k.unit = std::move(u);
  return k;
}

std::string KeySchema::fallback_json() const {
  struct Visit {
    std::string operator()(std::monostate) const { return "null"; }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(long long v) const { return std::to_string(v); }
    std::string operator()(double v) const { return json_number(v); }
    std::string operator()(const std::string& s) const { return json_string(s); }
    std::string operator()(const std::vector<double>& v) const { return json_list(v); }
  };
  return std::visit(Visit{}, fallback);
}

const char* key_type_name(KeyType t) {
  switch (t) {
    case KeyType::number:
      return "number";
    case KeyType::integer:
      return "integer";
    case KeyType::boolean:
      return "boolean";
    case KeyType::string:
      return "string";
    case KeyType::choice:
      return "choice";
    case KeyType::vector:
      return "vector";
    case KeyType::section:
      return "section";
    case KeyType::list:
      return "list";
  }
  return "?";
}

const char* need_name(Need n) {
  switch (n) {
    case Need::required:
      return "required";
    case Need::defaulted:
      return "defaulted";
    case Need::derived:
      return "derived";
    case Need::optional:
      return "optional";
  }
  return "?";
}

namespace {

std::string names_json(const std::vector<std::string>& names) {
  std::string out = "[";
  for (size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + json_string(names[i]);
  return out + "]";
}

std::string groups_json(const std::vector<std::vector<std::string>>& groups) {
  std::string out = "[";
  for (size_t i = 0; i < groups.size(); ++i) out += (i ? ", " : "") + names_json(groups[i]);
  return out + "]";
}

// Writes every mapping once, depth first in the order of the keys, so that the listing follows
// the order in which a scene is read.
class SchemaWriter {
 public:
  std::string run(const MappingSchema& root) {
    visit(root);
    std::string out = "{\n  \"format\": \"lbdem-scene-schema\",\n  \"version\": 1,\n";
    out += "  \"root\": " + json_string(root.path) + ",\n  \"mappings\": [\n";
    for (size_t i = 0; i < written_.size(); ++i) out += (i ? ",\n" : "") + written_[i];
    return out + "\n  ]\n}\n";
  }

 private:
  void visit(const MappingSchema& m) {
    if (!seen_.insert(&m).second) return;
    if (!paths_.insert(m.path).second)
      throw std::logic_error("scene schema: two mappings have the path '" + m.path + "'");
    std::string out = "    {\"path\": " + json_string(m.path) + ",\n";
    out += "     \"meaning\": " + json_string(m.meaning) + ",\n";
    out += "     \"keys\": " + keys(m.keys, "      ") + ",\n";
    out += "     \"alternatives\": [";
    for (size_t i = 0; i < m.alternatives.size(); ++i) {
      const Alternative& a = m.alternatives[i];
      out += std::string(i ? "," : "") + "\n      {\"key\": " + json_string(a.key) +
             ", \"value\": " + json_string(a.value) +
             ", \"exactly_one_of\": " + groups_json(a.exactly_one_of) +
             ",\n       \"keys\": " + keys(a.keys, "        ") + "}";
    }
    out += std::string(m.alternatives.empty() ? "" : "\n     ") + "],\n";
    out += "     \"exactly_one_of\": " + groups_json(m.exactly_one_of) + ",\n";
    out += "     \"at_least_one_of\": " + groups_json(m.at_least_one_of) + "}";
    written_.push_back(out);
    auto children = [&](const std::vector<KeySchema>& ks) {
      for (const auto& k : ks)
        if (k.mapping) visit(*k.mapping);
    };
    children(m.keys);
    for (const auto& a : m.alternatives) children(a.keys);
  }

  static std::string keys(const std::vector<KeySchema>& ks, const std::string& pad) {
    if (ks.empty()) return "[]";
    std::string out = "[";
    for (size_t i = 0; i < ks.size(); ++i) {
      out += i ? ",\n" : "\n";
      out += pad;
      out += key(ks[i]);
    }
    out += "\n";
    out.append(pad, 1, std::string::npos);
    out += "]";
    return out;
  }

  static std::string key(const KeySchema& k) {
    std::string out = "{\"name\": " + json_string(k.name) +
                      ", \"type\": " + json_string(key_type_name(k.type)) +
                      ", \"need\": " + json_string(need_name(k.need));
    if (k.need == Need::defaulted) out += ", \"default\": " + k.fallback_json();
    if (k.need == Need::derived || k.need == Need::optional)
      out += ", \"rule\": " + json_string(k.derived);
    if (!k.unit.empty()) out += ", \"unit\": " + json_string(k.unit);
    if (std::isfinite(k.bounds.lo))
      out += std::string(k.bounds.lo_open ? ", \"exclusive_minimum\": " : ", \"minimum\": ") +
             json_number(k.bounds.lo);
    if (std::isfinite(k.bounds.hi))
      out += std::string(k.bounds.hi_open ? ", \"exclusive_maximum\": " : ", \"maximum\": ") +
             json_number(k.bounds.hi);
    if (!k.values.empty()) out += ", \"values\": " + names_json(k.values);
    if (k.type == KeyType::vector) out += ", \"size\": " + std::to_string(k.size);
    if (k.mapping) out += ", \"mapping\": " + json_string(k.mapping->path);
    return out + ", \"meaning\": " + json_string(k.meaning) + "}";
  }

  std::set<const MappingSchema*> seen_;
  std::set<std::string> paths_;
  std::vector<std::string> written_;
};

}  // namespace

std::string scene_schema_json() {
  return SchemaWriter{}.run(scene_schema());
}

}  // namespace lbdem
