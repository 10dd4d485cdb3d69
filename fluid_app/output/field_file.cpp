#include "fluid_app/output/field_file.hpp"

#include <array>
#include <type_traits>

#include "coupler_lib/output/hdf5_handle.hpp"

namespace lbdem {

double si_velocity(double u_lattice, const UnitConverter& units) {
  return u_lattice * units.velocity();
}

double si_density(double rho_lattice, const UnitConverter& units) {
  return rho_lattice * units.rho;
}

double si_pressure(double rho_lattice, const UnitConverter& units) {
  return (rho_lattice - 1.0) / 3.0 * units.pressure();
}

namespace {

enum class Quantity { velocity, density, pressure };

// The local samples of one quantity, z slowest, converted to SI.
template <class T>
std::vector<T> gather_local(const FieldView& view, const LocalSelection& sel, const MacroFields& f,
                            Quantity q, const UnitConverter& units) {
  const int comps = q == Quantity::velocity ? 3 : 1;
  std::vector<T> out;
  out.reserve(static_cast<std::size_t>(sel.samples()) * comps);
  const FieldBlock& b = f.box;
  for (int mk = sel.first[2]; mk < sel.first[2] + sel.count[2]; ++mk) {
    const int k = view.axes[2].start + mk * view.axes[2].stride - b.lo[2];
    for (int mj = sel.first[1]; mj < sel.first[1] + sel.count[1]; ++mj) {
      const int j = view.axes[1].start + mj * view.axes[1].stride - b.lo[1];
      for (int mi = sel.first[0]; mi < sel.first[0] + sel.count[0]; ++mi) {
        const int i = view.axes[0].start + mi * view.axes[0].stride - b.lo[0];
        const std::size_t c = b.index(i, j, k);
        switch (q) {
          case Quantity::velocity:
            for (int d = 0; d < 3; ++d) out.push_back(T(si_velocity(f.u[3 * c + d], units)));
            break;
          case Quantity::density:
            out.push_back(T(si_density(f.rho[c], units)));
            break;
          case Quantity::pressure:
            out.push_back(T(si_pressure(f.rho[c], units)));
            break;
        }
      }
    }
  }
  return out;
}

const char* quantity_name(Quantity q) {
  return q == Quantity::velocity ? "velocity" : q == Quantity::density ? "density" : "pressure";
}

const char* quantity_unit(Quantity q) {
  return q == Quantity::velocity ? "m/s" : q == Quantity::density ? "kg/m^3" : "Pa";
}

// The quantities `what` asks for, in the order of the file.
std::vector<Quantity> asked(const FieldQuantities& what) {
  std::vector<Quantity> q;
  if (what.velocity) q.push_back(Quantity::velocity);
  if (what.density) q.push_back(Quantity::density);
  if (what.pressure) q.push_back(Quantity::pressure);
  return q;
}

hid_t file_type(const FieldQuantities& what) {
  return what.double_precision ? H5T_IEEE_F64LE : H5T_IEEE_F32LE;
}

// Collective: the group of one view, with its origin and spacing.
H5Handle create_view_group(hid_t file, const FieldView& view, const UnitConverter& units) {
  H5Handle group(H5Gcreate2(file, view.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 H5Gclose, "creating group " + view.name);
  for (int d = 0; d < 3; ++d) {
    const char* axis = d == 0 ? "x" : d == 1 ? "y" : "z";
    write_attribute(group, std::string("origin_") + axis, (view.axes[d].start + 0.5) * units.dx);
    write_attribute(group, std::string("spacing_") + axis, view.axes[d].stride * units.dx);
  }
  return group;
}

// Collective: the dataset of one quantity over the whole view.
H5Handle create_quantity(hid_t group, const FieldView& view, Quantity q, hid_t type) {
  const int rank = q == Quantity::velocity ? 4 : 3;
  const std::array<hsize_t, 4> dims{hsize_t(view.axes[2].count), hsize_t(view.axes[1].count),
                                    hsize_t(view.axes[0].count), 3};
  H5Handle file_space(H5Screate_simple(rank, dims.data(), nullptr), H5Sclose, "file space");
  H5Handle dset(
      H5Dcreate2(group, quantity_name(q), type, file_space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose, std::string("creating dataset ") + quantity_name(q));
  write_attribute(dset, "units", std::string(quantity_unit(q)));
  return dset;
}

// Writes the samples of `f` that the view holds (`sel`) into `dset`. With a collective
// transfer every rank calls it, those without samples with empty selections.
template <class T>
void write_selection(hid_t dset, const FieldView& view, const LocalSelection& sel,
                     const MacroFields& f, Quantity q, const UnitConverter& units, hid_t dxpl) {
  const int rank = q == Quantity::velocity ? 4 : 3;
  const std::array<hsize_t, 4> start{hsize_t(sel.first[2]), hsize_t(sel.first[1]),
                                     hsize_t(sel.first[0]), 0};
  const std::array<hsize_t, 4> count{hsize_t(sel.count[2]), hsize_t(sel.count[1]),
                                     hsize_t(sel.count[0]), 3};
  const hid_t mem_type = std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_FLOAT;
  H5Handle file_space(H5Dget_space(dset), H5Sclose, "file space");
  std::vector<T> data = gather_local<T>(view, sel, f, q, units);
  if (data.empty()) data.resize(3);  // a valid buffer for the empty selection
  // (A rank without samples gets a 1-sample memory space, then selects none of it.)
  const std::array<hsize_t, 4> mem_dims = sel.empty() ? std::array<hsize_t, 4>{1, 1, 1, 3} : count;
  H5Handle mem_space(H5Screate_simple(rank, mem_dims.data(), nullptr), H5Sclose, "memory space");
  if (sel.empty()) {
    h5_check(H5Sselect_none(file_space), "empty file selection");
    h5_check(H5Sselect_none(mem_space), "empty memory selection");
  } else {
    h5_check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start.data(), nullptr, count.data(),
                                 nullptr),
             "selecting the rank's hyperslab");
  }
  h5_check(H5Dwrite(dset, mem_type, mem_space, file_space, dxpl, data.data()),
           std::string("writing ") + quantity_name(q));
}

template <class T>
void write_view(hid_t file, const FieldView& view, const FieldQuantities& what,
                const MacroFields& f, const UnitConverter& units, hid_t dxpl) {
  const H5Handle group = create_view_group(file, view, units);
  const LocalSelection sel = local_selection(view, f.box);
  for (Quantity q : asked(what)) {
    const H5Handle dset = create_quantity(group, view, q, file_type(what));
    write_selection<T>(dset, view, sel, f, q, units, dxpl);
  }
}

void write_time_attributes(hid_t file, const UnitConverter& units, long step, double time) {
  write_attribute(file, "time", time);
  write_attribute(file, "step", static_cast<long long>(step));
  write_attribute(file, "dx", units.dx);
  write_attribute(file, "dt", units.dt);
}

}  // namespace

void write_field_file(const std::string& path, MPI_Comm comm, const std::vector<FieldView>& views,
                      const FieldQuantities& what, const MacroFields& fields,
                      const UnitConverter& units, long step, double time) {
  H5Handle file = create_parallel_file(path, comm);
  write_time_attributes(file, units, step, time);
  H5Handle dxpl = collective_transfer();
  for (const auto& v : views) {
    if (what.double_precision)
      write_view<double>(file, v, what, fields, units, dxpl);
    else
      write_view<float>(file, v, what, fields, units, dxpl);
  }
}

FieldFileWriter::FieldFileWriter(const std::string& path, MPI_Comm comm,
                                 const std::array<int, 3>& global, const FieldQuantities& what,
                                 const UnitConverter& units, long step, double time)
    : view_(volume_view(global, 1)), what_(what), units_(units) {
  file_ = create_parallel_file(path, comm);
  write_time_attributes(file_, units, step, time);
  group_ = create_view_group(file_, view_, units);
  for (Quantity q : asked(what))
    datasets_.push_back(create_quantity(group_, view_, q, file_type(what)));
  // Independent transfers: each rank writes its slabs when it has them, as many as it has.
  dxpl_ = H5Handle(H5Pcreate(H5P_DATASET_XFER), H5Pclose, "transfer list");
  h5_check(H5Pset_dxpl_mpio(dxpl_, H5FD_MPIO_INDEPENDENT), "H5Pset_dxpl_mpio");
}

void FieldFileWriter::write(const MacroFields& slab) {
  const LocalSelection sel = local_selection(view_, slab.box);
  if (sel.empty()) return;
  const std::vector<Quantity> qs = asked(what_);
  for (std::size_t k = 0; k < qs.size(); ++k) {
    if (what_.double_precision)
      write_selection<double>(datasets_[k], view_, sel, slab, qs[k], units_, dxpl_);
    else
      write_selection<float>(datasets_[k], view_, sel, slab, qs[k], units_, dxpl_);
  }
}

void FieldFileWriter::close() {
  datasets_.clear();
  group_.reset();
  dxpl_.reset();
  file_.reset();
}

}  // namespace lbdem
