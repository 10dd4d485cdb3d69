#pragma once
// A view is the set of lattice nodes one output product holds: the whole volume, subsampled
// with a stride, or one plane of nodes (a slice). Each axis is sampled as
// start, start + stride, ..., and each rank writes the samples that fall inside its block.
#include <array>
#include <string>
#include <vector>

#include "coupler_lib/scene/fluid_output_section.hpp"
#include "fluid_app/output/macro_fields.hpp"

namespace lbdem {

struct AxisSampling {
  int start = 0;   // first global node index
  int stride = 1;  // distance between samples in nodes
  int count = 0;   // number of samples
};

struct FieldView {
  std::string name;  // group in the HDF5 file and part of the XDMF file name
  std::array<AxisSampling, 3> axes{};
  long long samples() const {
    return static_cast<long long>(axes[0].count) * axes[1].count * axes[2].count;
  }
};

// Every stride-th node along each axis, starting at node 0.
FieldView volume_view(const std::array<int, 3>& global, int stride);
// The plane of nodes at slice.index normal to slice.axis, strided in-plane.
FieldView slice_view(const std::array<int, 3>& global, int stride, const FieldSlice& slice);
// Every view a field-output section asks for, in a fixed order (volume first).
std::vector<FieldView> views_for(const FieldOutputParams& p, const std::array<int, 3>& global);

// The samples of a view that lie in one rank's block: sample indices [first, first + count)
// per axis (count 0 on some axis: the rank holds none).
struct LocalSelection {
  std::array<int, 3> first{};
  std::array<int, 3> count{};
  bool empty() const { return count[0] == 0 || count[1] == 0 || count[2] == 0; }
  long long samples() const { return static_cast<long long>(count[0]) * count[1] * count[2]; }
};

LocalSelection local_selection(const FieldView& view, const FieldBlock& box);

}  // namespace lbdem
