#include "fluid_app/output/field_view.hpp"

#include <algorithm>

namespace lbdem {

namespace {
int samples_along(int n, int stride) {
  return (n + stride - 1) / stride;
}
}  // namespace

FieldView volume_view(const std::array<int, 3>& global, int stride) {
  FieldView v;
  v.name = "volume";
  for (int d = 0; d < 3; ++d) v.axes[d] = {0, stride, samples_along(global[d], stride)};
  return v;
}

FieldView slice_view(const std::array<int, 3>& global, int stride, const FieldSlice& slice) {
  FieldView v = volume_view(global, stride);
  v.name = slice.name;
  v.axes[slice.axis] = {slice.index, 1, 1};
  return v;
}

std::vector<FieldView> views_for(const FieldOutputParams& p, const std::array<int, 3>& global) {
  std::vector<FieldView> out;
  if (p.volume) out.push_back(volume_view(global, p.stride));
  for (const auto& s : p.slices) out.push_back(slice_view(global, p.stride, s));
  return out;
}

LocalSelection local_selection(const FieldView& view, const FieldBlock& box) {
  LocalSelection sel;
  for (int d = 0; d < 3; ++d) {
    const AxisSampling& a = view.axes[d];
    const int lo = box.lo[d], hi = box.lo[d] + box.n[d];  // [lo, hi)
    // Smallest m with start + m*stride >= lo, largest with start + m*stride < hi.
    const int first = lo <= a.start ? 0 : (lo - a.start + a.stride - 1) / a.stride;
    const int last = hi <= a.start ? -1 : std::min(a.count - 1, (hi - 1 - a.start) / a.stride);
    sel.first[d] = first;
    sel.count[d] = std::max(0, last - first + 1);
  }
  return sel;
}

}  // namespace lbdem
