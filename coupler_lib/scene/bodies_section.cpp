#include "coupler_lib/scene/bodies_section.hpp"

#include "coupler_lib/scene/bodies_file.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lbdem {

namespace {

// SplitMix64: a fully specified generator, so a seed gives the same bodies everywhere.
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

// Uniformly distributed rotation (Shoemake, Graphics Gems III, "Uniform random rotations").
std::array<double, 4> random_quaternion(SplitMix64& rng) {
  const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const double t2 = 2.0 * std::numbers::pi * u2, t3 = 2.0 * std::numbers::pi * u3;
  return {b * std::cos(t3), a * std::sin(t2), a * std::cos(t2), b * std::sin(t3)};
}

std::array<double, 4> read_quaternion(Section& s, const std::string& key) {
  auto q = s.numbers(key);
  if (q.size() != 4)
    s.fail(key, "expected 4 numbers [w, x, y, z], got " + std::to_string(q.size()));
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(n > 1e-12)) s.fail(key, "the quaternion must not be zero");
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

int find_shape(Section& s, const std::vector<ShapeParams>& shapes) {
  const auto name = s.require<std::string>("shape");
  for (size_t i = 0; i < shapes.size(); ++i)
    if (shapes[i].name == name) return static_cast<int>(i);
  s.fail("shape", "no shape named '" + name + "' in the shapes catalogue");
}

BodyParams parse_body(Section& s, const std::vector<ShapeParams>& shapes) {
  BodyParams b;
  b.shape = find_shape(s, shapes);
  b.position = s.require_vec3("position");
  if (s.has("orientation")) b.orientation = read_quaternion(s, "orientation");
  b.velocity = s.vec3("velocity");
  b.angular_velocity = s.vec3("angular_velocity");
  b.density = s.require<double>("density");
  s.finish();
  return b;
}

BodyGenerator parse_generator(Section& s, const std::vector<ShapeParams>& shapes) {
  BodyGenerator g;
  g.pattern = value_of(kBodyPatternWords, s.require_choice("generate"));
  g.shape = find_shape(s, shapes);
  const auto extent = analytic_extent(shapes[static_cast<size_t>(g.shape)]);
  g.density = s.require<double>("density");
  auto region = s.section("region");
  g.lo = region.require_vec3("lo");
  g.hi = region.require_vec3("hi");
  region.finish();
  if (s.has("min_distance") || !extent) {
    g.min_distance = s.require<double>("min_distance");
    g.bounding_radius = 0.5 * g.min_distance;
  } else {
    g.bounding_radius = extent->bounding_radius;
    g.min_distance = 2.0 * extent->bounding_radius;
  }
  const bool by_count = s.has("count");
  if (by_count == s.has("solid_fraction"))
    s.fail("", "a generator needs exactly one of 'count' and 'solid_fraction'");
  if (by_count) {
    g.count = s.require<long>("count");
  } else {
    const double phi = s.require<double>("solid_fraction");
    if (!extent)
      s.fail("solid_fraction", "needs a shape with a known volume (not stl); use 'count'");
    double v = 1;
    for (int d = 0; d < 3; ++d) v *= g.hi[d] - g.lo[d];
    g.count = std::lround(phi * v / extent->volume);
    if (g.count < 1) s.fail("solid_fraction", "gives no body at all in this region");
  }
  g.seed = static_cast<std::uint64_t>(s.get<long long>("seed"));
  if (s.has("orientation")) {
    g.random_orientation = false;
    g.orientation = read_quaternion(s, "orientation");
  }
  g.velocity = s.vec3("velocity");
  g.angular_velocity = s.vec3("angular_velocity");
  s.finish();
  return g;
}

}  // namespace

std::vector<BodyParams> generate_bodies(const BodyGenerator& g, const Section& where) {
  std::array<double, 3> lo{}, len{};
  for (int d = 0; d < 3; ++d) {
    lo[d] = g.lo[d] + g.bounding_radius;
    len[d] = (g.hi[d] - g.bounding_radius) - lo[d];
    if (len[d] < 0)
      where.fail("region", std::string("the region is thinner than one body along ") + "xyz"[d]);
  }
  std::vector<std::array<double, 3>> centres;
  SplitMix64 rng{g.seed};
  if (g.pattern == BodyPattern::lattice) {
    // The densest simple cubic lattice with spacing >= min_distance that fits, filled x fastest
    // then y then z, so a partial last layer sits on top.
    std::array<long, 3> n{};
    for (int d = 0; d < 3; ++d) n[d] = 1 + static_cast<long>(std::floor(len[d] / g.min_distance));
    if (n[0] * n[1] * n[2] < g.count)
      where.fail("", "lattice: " + std::to_string(g.count) + " bodies do not fit in the region; " +
                         "at most " + std::to_string(n[0] * n[1] * n[2]) + " with centre spacing " +
                         std::to_string(g.min_distance) + " m");
    // Centred in x and y, from the floor of the region in z.
    const long layers_xy = n[0] * n[1];
    const long nz = (g.count + layers_xy - 1) / layers_xy;
    const double s = g.min_distance;
    for (long k = 0; k < nz; ++k)
      for (long j = 0; j < n[1]; ++j)
        for (long i = 0; i < n[0]; ++i) {
          if (static_cast<long>(centres.size()) == g.count) break;
          const double off_x = 0.5 * (len[0] - static_cast<double>(n[0] - 1) * s);
          const double off_y = 0.5 * (len[1] - static_cast<double>(n[1] - 1) * s);
          centres.push_back({lo[0] + off_x + static_cast<double>(i) * s,
                             lo[1] + off_y + static_cast<double>(j) * s,
                             lo[2] + static_cast<double>(k) * s});
        }
  } else {
    // Random sequential addition, checked against a cell grid of size min_distance.
    const double h = g.min_distance;
    std::array<long, 3> nc{};
    for (int d = 0; d < 3; ++d) nc[d] = std::max(1L, static_cast<long>(std::ceil(len[d] / h)));
    std::vector<std::vector<int>> cells(static_cast<size_t>(nc[0] * nc[1] * nc[2]));
    auto cell_of = [&](const std::array<double, 3>& x, int d) {
      return std::clamp(static_cast<long>((x[d] - lo[d]) / h), 0L, nc[d] - 1);
    };
    const long max_attempts = 1000 * g.count + 100000;
    long attempts = 0;
    while (static_cast<long>(centres.size()) < g.count) {
      if (++attempts > max_attempts)
        where.fail("", "random: placed only " + std::to_string(centres.size()) + " of " +
                           std::to_string(g.count) + " bodies without overlap after " +
                           std::to_string(max_attempts) +
                           " attempts; lower count/solid_fraction or use 'lattice'");
      std::array<double, 3> x{};
      for (int d = 0; d < 3; ++d) x[d] = lo[d] + rng.uniform() * len[d];
      const long ci = cell_of(x, 0), cj = cell_of(x, 1), ck = cell_of(x, 2);
      bool free = true;
      for (long k = std::max(0L, ck - 1); free && k <= std::min(nc[2] - 1, ck + 1); ++k)
        for (long j = std::max(0L, cj - 1); free && j <= std::min(nc[1] - 1, cj + 1); ++j)
          for (long i = std::max(0L, ci - 1); free && i <= std::min(nc[0] - 1, ci + 1); ++i)
            for (int other : cells[static_cast<size_t>(i + nc[0] * (j + nc[1] * k))]) {
              const auto& y = centres[static_cast<size_t>(other)];
              const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
              if (dx * dx + dy * dy + dz * dz < h * h) {
                free = false;
                break;
              }
            }
      if (!free) continue;
      cells[static_cast<size_t>(ci + nc[0] * (cj + nc[1] * ck))].push_back(
          static_cast<int>(centres.size()));
      centres.push_back(x);
    }
  }
  std::vector<BodyParams> out;
  out.reserve(centres.size());
  for (const auto& c : centres) {
    BodyParams b;
    b.shape = g.shape;
    b.position = c;
    b.orientation = g.random_orientation ? random_quaternion(rng) : g.orientation;
    b.velocity = g.velocity;
    b.angular_velocity = g.angular_velocity;
    b.density = g.density;
    out.push_back(b);
  }
  return out;
}

namespace {

const MappingSchema& region_schema() {
  static const MappingSchema m{"bodies[].region",
                               "box the bodies lie in entirely",
                               {key::vec3("lo", "lower corner in m").required().in("m"),
                                key::vec3("hi", "upper corner in m").required().in("m")}};
  return m;
}

KeySchema orientation(std::string absent) {
  return key::vector("orientation", 4,
                     "orientation quaternion [w, x, y, z], shape frame -> space frame")
      .absent_means(std::move(absent));
}

}  // namespace

const MappingSchema& body_schema() {
  static const MappingSchema m{
      "bodies[]",
      "one entry of bodies: a single body, a generator (generate: ...) or a bodies file (file: "
      "...)",
      {},
      {{"generate",
        "",
        {key::choice("generate", words_of(kBodyPatternWords),
                     "lattice: simple cubic, filled from the lower corner; random: random "
                     "sequential addition")
             .required(),
         key::text("shape", "name of a shape in the catalogue").required(),
         key::number("density", "body density in kg/m^3")
             .required()
             .within(Bounds::positive())
             .in("kg/m^3"),
         key::section("region", region_schema(), "box the bodies lie in entirely").required(),
         key::number("min_distance",
                     "smallest centre distance in m (default: twice the bounding radius)")
             .derived_as("twice the shape's bounding radius; required for stl shapes")
             .within(Bounds::positive())
             .in("m"),
         key::integer("count", "number of bodies")
             .absent_means("give solid_fraction instead")
             .within(Bounds::at_least(1)),
         key::number("solid_fraction", "body volume / region volume")
             .absent_means("give count instead")
             .within({0.0, 1.0, true, true}),
         key::integer("seed", "random seed (orientations, random positions)").or_default(1),
         orientation("random orientations"),
         key::vec3("velocity", "initial velocity of every body in m/s")
             .or_default({0, 0, 0})
             .in("m/s"),
         key::vec3("angular_velocity", "initial angular velocity in rad/s")
             .or_default({0, 0, 0})
             .in("rad/s")},
        {{"count", "solid_fraction"}}},
       {"file", "", bodies_file_keys(), {}},
       {"",
        "",
        {key::text("shape", "name of a shape in the catalogue").required(),
         key::vec3("position", "centre of mass in m").required().in("m"),
         orientation("the shape frame (identity)"),
         key::vec3("velocity", "initial velocity in m/s").or_default({0, 0, 0}).in("m/s"),
         key::vec3("angular_velocity", "initial angular velocity in rad/s")
             .or_default({0, 0, 0})
             .in("rad/s"),
         key::number("density", "body density in kg/m^3")
             .required()
             .within(Bounds::positive())
             .in("kg/m^3")},
        {}}}};
  return m;
}

std::vector<BodyParams> parse_bodies(Section& root, const std::vector<ShapeParams>& shapes) {
  std::vector<BodyParams> out;
  for (auto& s : root.list("bodies")) {
    if (s.has("generate")) {
      const auto g = parse_generator(s, shapes);
      const auto placed = generate_bodies(g, s);
      out.insert(out.end(), placed.begin(), placed.end());
    } else if (s.has("file")) {
      const auto read = read_bodies_file(s, shapes);
      out.insert(out.end(), read.begin(), read.end());
    } else {
      out.push_back(parse_body(s, shapes));
    }
  }
  return out;
}

}  // namespace lbdem
