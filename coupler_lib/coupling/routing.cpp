#include "coupler_lib/coupling/routing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "coupler_lib/geometry/periodic.hpp"

namespace lbdem {

namespace {

double gap(double c, double lo, double hi) {
  return std::max({lo - c, 0.0, c - hi});
}

std::string axis_name(int d) {
  return std::string(1, "xyz"[d]);
}

}  // namespace

double FluidLayout::reach(int shape) const {
  if (shape < 0 || shape >= static_cast<int>(shape_radius.size()))
    throw std::out_of_range("shape index " + std::to_string(shape) + " outside the catalogue of " +
                            std::to_string(shape_radius.size()) + " shapes");
  return shape_radius[static_cast<size_t>(shape)] + margin;
}

double periodic_distance2(const FluidLayout& layout, const Box& box, const double x[3]) {
  // The squared distance is a sum over axes and the images along each periodic axis are
  // independent, so the nearest image is found axis by axis. With x wrapped into the domain
  // and the box inside it, only the images one period away can be nearer.
  double d2 = 0;
  for (int d = 0; d < 3; ++d) {
    double g;
    if (layout.periodic[d]) {
      const double lo = layout.domain.lo[d], len = layout.domain.hi[d] - lo;
      const double c = lo + wrap_periodic(x[d] - lo, len);
      g = std::min({gap(c, box.lo[d], box.hi[d]), gap(c - len, box.lo[d], box.hi[d]),
                    gap(c + len, box.lo[d], box.hi[d])});
    } else {
      g = gap(x[d], box.lo[d], box.hi[d]);
    }
    d2 += g * g;
  }
  return d2;
}

std::vector<int> touched_ranks(const FluidLayout& layout, const double x[3], double reach) {
  std::vector<int> out;
  const double r2 = reach * reach;
  for (size_t r = 0; r < layout.boxes.size(); ++r)
    if (periodic_distance2(layout, layout.boxes[r], x) <= r2) out.push_back(static_cast<int>(r));
  return out;
}

void validate_layout(const FluidLayout& layout) {
  if (layout.boxes.empty()) throw std::invalid_argument("fluid layout has no subdomain boxes");
  if (!(layout.margin >= 0))
    throw std::invalid_argument("stencil margin must be >= 0, got " +
                                std::to_string(layout.margin));
  const double slack = 1e-9;
  for (int d = 0; d < 3; ++d)
    if (!(layout.domain.hi[d] > layout.domain.lo[d]))
      throw std::invalid_argument("fluid domain is empty along " + axis_name(d));
  for (size_t r = 0; r < layout.boxes.size(); ++r) {
    const Box& b = layout.boxes[r];
    for (int d = 0; d < 3; ++d) {
      const double len = layout.domain.hi[d] - layout.domain.lo[d];
      if (!(b.hi[d] >= b.lo[d]) || b.lo[d] < layout.domain.lo[d] - slack * len ||
          b.hi[d] > layout.domain.hi[d] + slack * len)
        throw std::invalid_argument("box of fluid rank " + std::to_string(r) + " along " +
                                    axis_name(d) + " is [" + std::to_string(b.lo[d]) + ", " +
                                    std::to_string(b.hi[d]) + "], not inside the domain [" +
                                    std::to_string(layout.domain.lo[d]) + ", " +
                                    std::to_string(layout.domain.hi[d]) + "]");
    }
  }
  for (size_t s = 0; s < layout.shape_radius.size(); ++s)
    if (!(layout.shape_radius[s] >= 0))
      throw std::invalid_argument("bounding radius of shape " + std::to_string(s) +
                                  " must be >= 0");
}

// Layout: [n_boxes, n_shapes, margin, domain(6), periodic(3), boxes(6 n), radii(n_shapes)].
std::vector<double> pack_layout(const FluidLayout& layout) {
  std::vector<double> f;
  f.push_back(static_cast<double>(layout.boxes.size()));
  f.push_back(static_cast<double>(layout.shape_radius.size()));
  f.push_back(layout.margin);
  auto put_box = [&](const Box& b) {
    f.insert(f.end(), b.lo.begin(), b.lo.end());
    f.insert(f.end(), b.hi.begin(), b.hi.end());
  };
  put_box(layout.domain);
  for (bool p : layout.periodic) f.push_back(p ? 1.0 : 0.0);
  for (const Box& b : layout.boxes) put_box(b);
  f.insert(f.end(), layout.shape_radius.begin(), layout.shape_radius.end());
  return f;
}

FluidLayout unpack_layout(std::span<const double> f) {
  if (f.size() < 12) throw std::invalid_argument("fluid layout message is too short");
  const auto nb = static_cast<size_t>(f[0]), ns = static_cast<size_t>(f[1]);
  if (f.size() != 12 + 6 * nb + ns)
    throw std::invalid_argument("fluid layout message has " + std::to_string(f.size()) +
                                " numbers, expected " + std::to_string(12 + 6 * nb + ns));
  FluidLayout l;
  l.margin = f[2];
  size_t i = 3;
  auto get_box = [&](Box& b) {
    for (int d = 0; d < 3; ++d) b.lo[d] = f[i++];
    for (int d = 0; d < 3; ++d) b.hi[d] = f[i++];
  };
  get_box(l.domain);
  for (int d = 0; d < 3; ++d) l.periodic[d] = f[i++] != 0.0;
  l.boxes.resize(nb);
  for (Box& b : l.boxes) get_box(b);
  l.shape_radius.assign(f.begin() + static_cast<std::ptrdiff_t>(i), f.end());
  return l;
}

}  // namespace lbdem
