#pragma once
// Positions and offsets along a periodic axis of length len (the paper's appendix, "How forces
// on particles are calculated": bodies near a periodic face act through their nearest image).
// One definition for both programs: routing, the body field, the kernel's body table and the
// momentum audit all wrap and take images the same way, so they agree bit for bit.
#include <cmath>

namespace lbdem {

// x wrapped into [0, len).
template <class T>
T wrap_periodic(T x, T len) {
  x -= len * std::floor(x / len);
  return x >= len ? x - len : x;  // x / len just below an integer can round x up to len
}

// The nearest image of an offset r: r shifted by a whole number of lengths into [-len/2, len/2].
template <class T>
T min_image(T r, T len) {
  return r - len * std::floor(r / len + T(0.5));
}

}  // namespace lbdem
