#include "coupler_lib/coupling/recording.hpp"

#include <hdf5.h>

#include <cstddef>
#include <filesystem>
#include <stdexcept>

#include "coupler_lib/output/hdf5_handle.hpp"

namespace lbdem {

namespace {

// One row of the step index tables.
struct StepRow {
  std::int64_t step;
  std::int64_t offset;
  std::int64_t count;
};

constexpr hsize_t kChunk = 1024;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": HDF5 error while " + what);
}

hid_t check(hid_t id, const std::string& path, const std::string& what) {
  if (id < 0) fail(path, what);
  return id;
}

// Closes an HDF5 handle at scope exit (the project's one handle type).
using Handle = H5Handle;

hid_t array_of(hid_t base, hsize_t n) {
  return H5Tarray_create2(base, 1, &n);
}

hid_t state_type() {
  hid_t t = H5Tcreate(H5T_COMPOUND, sizeof(BodyState));
  H5Tinsert(t, "version", offsetof(BodyState, version), H5T_NATIVE_UINT32);
  H5Tinsert(t, "shape", offsetof(BodyState, shape), H5T_NATIVE_INT32);
  H5Tinsert(t, "id", offsetof(BodyState, id), H5T_NATIVE_INT64);
  H5Tinsert(t, "step", offsetof(BodyState, step), H5T_NATIVE_INT64);
  const Handle a3(array_of(H5T_NATIVE_DOUBLE, 3), H5Tclose),
      a4(array_of(H5T_NATIVE_DOUBLE, 4), H5Tclose);
  H5Tinsert(t, "x", offsetof(BodyState, x), a3);
  H5Tinsert(t, "q", offsetof(BodyState, q), a4);
  H5Tinsert(t, "v", offsetof(BodyState, v), a3);
  H5Tinsert(t, "w", offsetof(BodyState, w), a3);
  return t;
}

hid_t load_type() {
  hid_t t = H5Tcreate(H5T_COMPOUND, sizeof(BodyLoad));
  H5Tinsert(t, "version", offsetof(BodyLoad, version), H5T_NATIVE_UINT32);
  H5Tinsert(t, "pad", offsetof(BodyLoad, pad), H5T_NATIVE_INT32);
  H5Tinsert(t, "id", offsetof(BodyLoad, id), H5T_NATIVE_INT64);
  H5Tinsert(t, "step", offsetof(BodyLoad, step), H5T_NATIVE_INT64);
  const Handle a3(array_of(H5T_NATIVE_DOUBLE, 3), H5Tclose);
  H5Tinsert(t, "f", offsetof(BodyLoad, f), a3);
  H5Tinsert(t, "t", offsetof(BodyLoad, t), a3);
  return t;
}

hid_t row_type() {
  hid_t t = H5Tcreate(H5T_COMPOUND, sizeof(StepRow));
  H5Tinsert(t, "step", offsetof(StepRow, step), H5T_NATIVE_INT64);
  H5Tinsert(t, "offset", offsetof(StepRow, offset), H5T_NATIVE_INT64);
  H5Tinsert(t, "count", offsetof(StepRow, count), H5T_NATIVE_INT64);
  return t;
}

// A growing 1-D table of one compound type.
class Table {
 public:
  Table(hid_t file, const char* name, hid_t type, const std::string& path) : path_(path) {
    const hsize_t zero = 0, unlimited = H5S_UNLIMITED;
    const Handle space(H5Screate_simple(1, &zero, &unlimited), H5Sclose);
    const Handle props(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    H5Pset_chunk(props, 1, &kChunk);
    set_ = check(H5Dcreate2(file, name, type, space, H5P_DEFAULT, props, H5P_DEFAULT), path,
                 std::string("creating ") + name);
    type_ = type;
  }
  ~Table() { H5Dclose(set_); }
  Table(const Table&) = delete;
  Table& operator=(const Table&) = delete;
  hsize_t size() const { return size_; }

  void append(const void* rows, hsize_t n) {
    if (n == 0) return;
    const hsize_t grown = size_ + n;
    if (H5Dset_extent(set_, &grown) < 0) fail(path_, "growing a table");
    const Handle file_space(H5Dget_space(set_), H5Sclose);
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, &size_, nullptr, &n, nullptr);
    const Handle mem(H5Screate_simple(1, &n, nullptr), H5Sclose);
    if (H5Dwrite(set_, type_, mem, file_space, H5P_DEFAULT, rows) < 0)
      fail(path_, "writing a table");
    size_ = grown;
  }

 private:
  std::string path_;
  hid_t set_ = -1;
  hid_t type_ = -1;
  hsize_t size_ = 0;
};

template <class T>
void write_attribute(hid_t obj, const char* name, hid_t type, const T& value,
                     const std::string& path) {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle a(check(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), path,
                       std::string("writing attribute ") + name),
                 H5Aclose);
  H5Awrite(a, type, &value);
}

template <class T>
T read_attribute(hid_t obj, const char* name, hid_t type, const std::string& path) {
  T value{};
  const Handle a(check(H5Aopen(obj, name, H5P_DEFAULT), path,
                       std::string("reading attribute ") + name + " (not a recording?)"),
                 H5Aclose);
  if (H5Aread(a, type, &value) < 0) fail(path, std::string("reading attribute ") + name);
  return value;
}

void write_string_attribute(hid_t obj, const char* name, const std::string& s,
                            const std::string& path) {
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, s.size() + 1);
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle a(check(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), path,
                       std::string("writing attribute ") + name),
                 H5Aclose);
  H5Awrite(a, type, s.c_str());
}

std::string read_string_attribute(hid_t obj, const char* name, const std::string& path) {
  const Handle a(
      check(H5Aopen(obj, name, H5P_DEFAULT), path, std::string("reading attribute ") + name),
      H5Aclose);
  const Handle type(H5Aget_type(a), H5Tclose);
  std::string s(H5Tget_size(type), '\0');
  if (H5Aread(a, type, s.data()) < 0) fail(path, std::string("reading attribute ") + name);
  return s.substr(0, s.find('\0'));
}

template <class T>
std::vector<T> read_rows(hid_t file, const char* name, hid_t type, hsize_t offset, hsize_t n,
                         const std::string& path) {
  std::vector<T> rows(n);
  if (n == 0) return rows;
  const Handle set(check(H5Dopen2(file, name, H5P_DEFAULT), path,
                         std::string("opening ") + name + " (not a recording?)"),
                   H5Dclose);
  const Handle file_space(H5Dget_space(set), H5Sclose);
  H5Sselect_hyperslab(file_space, H5S_SELECT_SET, &offset, nullptr, &n, nullptr);
  const Handle mem(H5Screate_simple(1, &n, nullptr), H5Sclose);
  if (H5Dread(set, type, mem, file_space, H5P_DEFAULT, rows.data()) < 0)
    fail(path, std::string("reading ") + name);
  return rows;
}

hsize_t rows_in(hid_t file, const char* name, const std::string& path) {
  const Handle set(check(H5Dopen2(file, name, H5P_DEFAULT), path,
                         std::string("opening ") + name + " (not a recording?)"),
                   H5Dclose);
  const Handle space(H5Dget_space(set), H5Sclose);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  return n;
}

}  // namespace

struct RecordingWriter::Impl {
  std::string path;
  hid_t file = -1;
  hid_t tstate = -1, tload = -1, trow = -1;
  std::unique_ptr<Table> states, loads, state_steps, load_steps;

  ~Impl() {
    states.reset();
    loads.reset();
    state_steps.reset();
    load_steps.reset();
    for (hid_t t : {tstate, tload, trow})
      if (t >= 0) H5Tclose(t);
    if (file >= 0) H5Fclose(file);
  }
};

RecordingWriter::RecordingWriter(const std::string& path, const RecordingInfo& info)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = path;
  m.file = check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), path,
                 "creating the recording (is the folder writable?)");
  m.tstate = state_type();
  m.tload = load_type();
  m.trow = row_type();
  write_attribute(m.file, "protocol_version", H5T_NATIVE_UINT32, info.protocol, path);
  write_attribute(m.file, "scene_hash", H5T_NATIVE_UINT64, info.scene_hash, path);
  write_attribute(m.file, "fluid_ranks", H5T_NATIVE_INT, info.fluid_ranks, path);
  write_attribute(m.file, "dem_ranks", H5T_NATIVE_INT, info.dem_ranks, path);
  write_string_attribute(m.file, "scene_file", info.scene_file, path);
  const std::vector<double> layout = pack_layout(info.layout);
  const hsize_t n = layout.size();
  const Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  const Handle set(check(H5Dcreate2(m.file, "fluid_layout", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT,
                                    H5P_DEFAULT, H5P_DEFAULT),
                         path, "writing fluid_layout"),
                   H5Dclose);
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, layout.data());
  m.states = std::make_unique<Table>(m.file, "states", m.tstate, path);
  m.loads = std::make_unique<Table>(m.file, "loads", m.tload, path);
  m.state_steps = std::make_unique<Table>(m.file, "state_steps", m.trow, path);
  m.load_steps = std::make_unique<Table>(m.file, "load_steps", m.trow, path);
}

RecordingWriter::~RecordingWriter() = default;

void RecordingWriter::append_states(std::int64_t step, std::span<const BodyState> states) {
  const StepRow row{step, static_cast<std::int64_t>(impl_->states->size()),
                    static_cast<std::int64_t>(states.size())};
  impl_->states->append(states.data(), states.size());
  impl_->state_steps->append(&row, 1);
}

void RecordingWriter::append_loads(std::int64_t step, std::span<const BodyLoad> loads) {
  const StepRow row{step, static_cast<std::int64_t>(impl_->loads->size()),
                    static_cast<std::int64_t>(loads.size())};
  impl_->loads->append(loads.data(), loads.size());
  impl_->load_steps->append(&row, 1);
}

void RecordingWriter::flush() {
  if (H5Fflush(impl_->file, H5F_SCOPE_GLOBAL) < 0) fail(impl_->path, "flushing");
}

struct RecordingReader::Impl {
  std::string path;
  hid_t file = -1;
  hid_t tstate = -1, tload = -1, trow = -1;
  RecordingInfo info;
  std::map<std::int64_t, StepRow> state_rows, load_rows;

  ~Impl() {
    for (hid_t t : {tstate, tload, trow})
      if (t >= 0) H5Tclose(t);
    if (file >= 0) H5Fclose(file);
  }

  const StepRow& row(const std::map<std::int64_t, StepRow>& rows, std::int64_t step,
                     const char* what) const {
    const auto it = rows.find(step);
    if (it == rows.end())
      throw std::runtime_error(
          path + ": no " + what + " recorded for step " + std::to_string(step) +
          (rows.empty() ? std::string(" (none recorded)")
                        : " (recorded steps " + std::to_string(rows.begin()->first) + " to " +
                              std::to_string(rows.rbegin()->first) + ")"));
    return it->second;
  }
};

RecordingReader::RecordingReader(const std::string& path) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = path;
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": recording not found");
  if (H5Fis_hdf5(path.c_str()) <= 0)
    throw std::runtime_error(path + ": not an HDF5 file, so not a recording");
  m.file = check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path, "opening");
  m.tstate = state_type();
  m.tload = load_type();
  m.trow = row_type();
  m.info.protocol =
      read_attribute<std::uint32_t>(m.file, "protocol_version", H5T_NATIVE_UINT32, path);
  if (m.info.protocol != kProtocolVersion)
    throw std::runtime_error(path + ": recorded with coupling protocol version " +
                             std::to_string(m.info.protocol) + ", this build speaks version " +
                             std::to_string(kProtocolVersion));
  m.info.scene_hash = read_attribute<std::uint64_t>(m.file, "scene_hash", H5T_NATIVE_UINT64, path);
  m.info.fluid_ranks = read_attribute<int>(m.file, "fluid_ranks", H5T_NATIVE_INT, path);
  m.info.dem_ranks = read_attribute<int>(m.file, "dem_ranks", H5T_NATIVE_INT, path);
  m.info.scene_file = read_string_attribute(m.file, "scene_file", path);
  const hsize_t nl = rows_in(m.file, "fluid_layout", path);
  const auto flat = read_rows<double>(m.file, "fluid_layout", H5T_NATIVE_DOUBLE, 0, nl, path);
  m.info.layout = unpack_layout(flat);
  for (auto [name, rows] :
       {std::pair{"state_steps", &m.state_rows}, std::pair{"load_steps", &m.load_rows}}) {
    const hsize_t n = rows_in(m.file, name, path);
    for (const StepRow& r : read_rows<StepRow>(m.file, name, m.trow, 0, n, path))
      (*rows)[r.step] = r;
  }
}

RecordingReader::~RecordingReader() = default;

const RecordingInfo& RecordingReader::info() const {
  return impl_->info;
}

std::vector<BodyState> RecordingReader::states(std::int64_t step) const {
  const StepRow& r = impl_->row(impl_->state_rows, step, "states");
  return read_rows<BodyState>(impl_->file, "states", impl_->tstate, static_cast<hsize_t>(r.offset),
                              static_cast<hsize_t>(r.count), impl_->path);
}

std::vector<BodyLoad> RecordingReader::loads(std::int64_t step) const {
  const StepRow& r = impl_->row(impl_->load_rows, step, "loads");
  return read_rows<BodyLoad>(impl_->file, "loads", impl_->tload, static_cast<hsize_t>(r.offset),
                             static_cast<hsize_t>(r.count), impl_->path);
}

std::vector<std::int64_t> RecordingReader::state_steps() const {
  std::vector<std::int64_t> s;
  for (const auto& [k, v] : impl_->state_rows) s.push_back(k);
  return s;
}

std::vector<std::int64_t> RecordingReader::load_steps() const {
  std::vector<std::int64_t> s;
  for (const auto& [k, v] : impl_->load_rows) s.push_back(k);
  return s;
}

}  // namespace lbdem
