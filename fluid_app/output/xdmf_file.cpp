#include "fluid_app/output/xdmf_file.hpp"

#include "coupler_lib/output/xdmf.hpp"

namespace lbdem {

std::string xdmf_text(const FieldView& view, const FieldQuantities& what, double dx,
                      const std::vector<XdmfStep>& steps) {
  // XDMF lists dimensions, origin and spacing slowest axis first: z, y, x.
  const auto& a = view.axes;
  XdmfLattice lattice;
  for (int i = 0; i < 3; ++i) {
    const auto& axis = a[2 - i];
    lattice.dims[i] = axis.count;
    lattice.origin[i] = (axis.start + 0.5) * dx;  // the first node's cell centre
    lattice.spacing[i] = axis.stride * dx;
  }
  const int precision = what.double_precision ? 8 : 4;
  std::vector<XdmfGrid> grids;
  for (const auto& s : steps) {
    XdmfGrid g{view.name, s.time, lattice, {}};
    auto field = [&](const char* name, bool vector) {
      std::vector<long> dims(lattice.dims.begin(), lattice.dims.end());
      if (vector) dims.push_back(3);
      const std::string source = s.h5_file + ":/" + view.name + "/" + name;
      g.attributes.push_back(
          {name, vector ? "Vector" : "Scalar", {dims, "Float", precision, source}});
    };
    if (what.velocity) field("velocity", true);
    if (what.density) field("density", false);
    if (what.pressure) field("pressure", false);
    grids.push_back(std::move(g));
  }
  return xdmf_series(view.name, grids);
}

}  // namespace lbdem
