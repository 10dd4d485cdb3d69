#include "coupler_lib/coupling/compare.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace lbdem {

namespace {

std::string number(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

struct Field {
  const char* name;
  int count;
  std::function<const double*(const void*)> get;
};

template <class Packet>
std::optional<std::string> compare(std::int64_t step, std::span<const Packet> rec,
                                   std::span<const Packet> rep, const std::vector<Field>& fields,
                                   int shape_of(const Packet&)) {
  const std::string at = "step " + std::to_string(step) + ", ";
  const size_t n = std::min(rec.size(), rep.size());
  for (size_t i = 0; i < n; ++i) {
    const Packet& a = rec[i];
    const Packet& b = rep[i];
    if (a.id != b.id)
      return at + "packet " + std::to_string(i) + ": recorded body " + std::to_string(a.id) +
             ", replayed body " + std::to_string(b.id);
    const std::string body = at + "body " + std::to_string(a.id) + ", ";
    if (shape_of(a) != shape_of(b))
      return body + "shape: recorded " + std::to_string(shape_of(a)) + ", replayed " +
             std::to_string(shape_of(b));
    for (const Field& f : fields) {
      const double* x = f.get(&a);
      const double* y = f.get(&b);
      for (int k = 0; k < f.count; ++k)
        if (!same_bits(x[k], y[k]))
          return body + f.name + "[" + std::to_string(k) + "]: recorded " + number(x[k]) +
                 ", replayed " + number(y[k]);
    }
  }
  if (rec.size() != rep.size())
    return at + "recorded " + std::to_string(rec.size()) + " bodies, replayed " +
           std::to_string(rep.size());
  return std::nullopt;
}

int state_shape(const BodyState& s) {
  return s.shape;
}
int load_shape(const BodyLoad&) {
  return 0;
}

}  // namespace

std::optional<std::string> first_mismatch(std::int64_t step, std::span<const BodyState> recorded,
                                          std::span<const BodyState> replayed) {
  auto s = [](const void* p) { return static_cast<const BodyState*>(p); };
  static const std::vector<Field> fields = {{"x", 3, [s](const void* p) { return s(p)->x; }},
                                            {"q", 4, [s](const void* p) { return s(p)->q; }},
                                            {"v", 3, [s](const void* p) { return s(p)->v; }},
                                            {"w", 3, [s](const void* p) { return s(p)->w; }}};
  return compare(step, recorded, replayed, fields, state_shape);
}

std::optional<std::string> first_mismatch(std::int64_t step, std::span<const BodyLoad> recorded,
                                          std::span<const BodyLoad> replayed) {
  auto l = [](const void* p) { return static_cast<const BodyLoad*>(p); };
  static const std::vector<Field> fields = {{"f", 3, [l](const void* p) { return l(p)->f; }},
                                            {"t", 3, [l](const void* p) { return l(p)->t; }}};
  return compare(step, recorded, replayed, fields, load_shape);
}

std::vector<BodyLoad> loads_of(std::span<const std::int64_t> owned,
                               std::span<const BodyLoad> recorded, const std::string& source,
                               std::int64_t step) {
  std::unordered_map<std::int64_t, const BodyLoad*> by_id;
  for (const BodyLoad& l : recorded) by_id.emplace(l.id, &l);
  std::vector<BodyLoad> mine;
  mine.reserve(owned.size());
  for (std::int64_t id : owned) {
    const auto it = by_id.find(id);
    if (it == by_id.end())
      throw std::runtime_error(source + ": no load recorded for body " + std::to_string(id) +
                               " at step " + std::to_string(step));
    mine.push_back(*it->second);
  }
  return mine;
}

}  // namespace lbdem
