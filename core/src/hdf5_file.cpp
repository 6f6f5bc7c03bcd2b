#include "wearscale/core/hdf5_file.hpp"

#include <hdf5.h>

#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"

namespace wearscale {

namespace {

// Debian's serial HDF5 is not thread-safe: every call into it from these
// wrappers holds this lock, so sweeps can run cases on several threads.
std::recursive_mutex& hdf5_mutex() {
  static std::recursive_mutex m;
  return m;
}

// HDF5 prints its own error stack by default; wearscale reports errors itself.
void silence_hdf5() {
  static const bool once = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)once;
}

// Closes an HDF5 identifier when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*closer)(hid_t)) : id_(id), closer_(closer) {}
  ~Handle() {
    if (id_ >= 0) closer_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*closer_)(hid_t);
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what);
}

std::pair<std::string, std::string> split(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return {"/", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

void put_string_attribute(hid_t obj, const std::string& name, std::string_view value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  check(H5Tset_size(type, value.empty() ? 1 : value.size()), "string type");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "string charset");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  Handle attr(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) throw std::runtime_error("HDF5: cannot create attribute " + name);
  const std::string buf = value.empty() ? std::string(1, '\0') : std::string(value);
  check(H5Awrite(attr, type, buf.data()), "write attribute " + name);
}

void put_number_attribute(hid_t obj, const std::string& name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  Handle attr(H5Acreate2(obj, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) throw std::runtime_error("HDF5: cannot create attribute " + name);
  check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}

void write_dataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims, const double* data,
                   std::string_view unit) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  hsize_t total = 1;
  for (auto d : dims) total *= d;
  if (total >= 4096) {  // compress large fields; chunks of whole rows
    std::vector<hsize_t> chunk = dims;
    chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(dims[0], (1u << 16) / std::max<hsize_t>(1, total / dims[0])));
    check(H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data()), "chunk");
    check(H5Pset_shuffle(dcpl), "shuffle");
    check(H5Pset_deflate(dcpl, 4), "deflate");
  }
  if (H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0) check(H5Ldelete(parent, name.c_str(), H5P_DEFAULT), "replace " + name);
  Handle ds(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) throw std::runtime_error("HDF5: cannot create dataset " + name);
  check(H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + name);
  if (!unit.empty()) put_string_attribute(ds, "unit", unit);
}

// H5Lexists needs every intermediate link to exist: test the path one level at a time.
bool path_exists(hid_t file, const std::string& path) {
  if (path == "/") return true;
  std::size_t start = 1;
  while (start <= path.size()) {
    auto end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    if (H5Lexists(file, path.substr(0, end).c_str(), H5P_DEFAULT) <= 0) return false;
    start = end + 1;
  }
  return true;
}

}  // namespace

// ---------------------------------------------------------------- writer ---

H5Writer::H5Writer(std::filesystem::path final_path) : final_(std::move(final_path)) {
  std::lock_guard lock(hdf5_mutex());
  silence_hdf5();
  if (!final_.parent_path().empty()) std::filesystem::create_directories(final_.parent_path());
  partial_ = partial_path(final_);
  file_ = H5Fcreate(partial_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error("HDF5: cannot create " + partial_.string());
}

H5Writer::~H5Writer() {
  std::lock_guard lock(hdf5_mutex());
  if (committed_) return;
  close();
  std::error_code ec;
  std::filesystem::remove(partial_, ec);
}

void H5Writer::close() {
  std::lock_guard lock(hdf5_mutex());
  if (file_ >= 0) H5Fclose(file_);
  file_ = -1;
}

void H5Writer::ensure_group(const std::string& group_path) {
  std::lock_guard lock(hdf5_mutex());
  if (file_ < 0) throw std::logic_error("H5Writer: file already committed");
  std::string walked;
  std::size_t start = 1;
  while (start <= group_path.size() && group_path != "/") {
    auto end = group_path.find('/', start);
    if (end == std::string::npos) end = group_path.size();
    walked += '/';
    walked.append(group_path, start, end - start);
    if (H5Lexists(file_, walked.c_str(), H5P_DEFAULT) <= 0) {
      hid_t g = H5Gcreate2(file_, walked.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      if (g < 0) throw std::runtime_error("HDF5: cannot create group " + walked);
      H5Gclose(g);
    }
    start = end + 1;
  }
}

long long H5Writer::group(const std::string& path) {
  std::lock_guard lock(hdf5_mutex());
  const auto parent = split(path).first;
  ensure_group(parent);
  return H5Oopen(file_, parent.c_str(), H5P_DEFAULT);
}

void H5Writer::write_series(const std::string& path, std::span<const double> values, std::string_view unit) {
  std::lock_guard lock(hdf5_mutex());
  Handle g(group(path), H5Oclose);
  write_dataset(g, split(path).second, {static_cast<hsize_t>(values.size())}, values.data(), unit);
}

void H5Writer::write_table(const std::string& group_path, const std::vector<std::string>& names,
                           const std::vector<std::span<const double>>& columns, const std::vector<std::string>& units) {
  if (names.size() != columns.size() || (!units.empty() && units.size() != names.size()))
    throw std::invalid_argument("H5Writer::write_table: names, columns and units differ in count");
  std::string list;
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (columns[c].size() != columns[0].size())
      throw std::invalid_argument("H5Writer::write_table: column '" + names[c] + "' has a different length");
    write_series(group_path + "/" + names[c], columns[c], units.empty() ? "" : units[c]);
    list += (c ? "," : "") + names[c];
  }
  set_attribute(group_path, "columns", list);
}

void H5Writer::write_field(const std::string& path, const RealField& field, std::string_view unit) {
  std::lock_guard lock(hdf5_mutex());
  if (field.layout() != Layout::Physical) throw std::invalid_argument("H5Writer::write_field: spectral field");
  Handle g(group(path), H5Oclose);
  const auto name = split(path).second;
  write_dataset(g, name, {field.rows(), field.cols()}, field.data(), unit);
  Handle ds(H5Dopen2(g, name.c_str(), H5P_DEFAULT), H5Dclose);
  put_number_attribute(ds, "lx", field.grid().lx);
  put_number_attribute(ds, "ly", field.grid().ly);
}

void H5Writer::write_scalar(const std::string& path, double value, std::string_view unit) {
  std::lock_guard lock(hdf5_mutex());
  Handle g(group(path), H5Oclose);
  write_dataset(g, split(path).second, {1}, &value, unit);
}

void H5Writer::set_attribute(const std::string& object, const std::string& name, std::string_view value) {
  std::lock_guard lock(hdf5_mutex());
  if (!H5Writer::exists(object)) ensure_group(object);
  Handle obj(H5Oopen(file_, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!obj.valid()) throw std::runtime_error("HDF5: no object " + object);
  put_string_attribute(obj, name, value);
}

void H5Writer::set_attribute(const std::string& object, const std::string& name, double value) {
  std::lock_guard lock(hdf5_mutex());
  if (!H5Writer::exists(object)) ensure_group(object);
  Handle obj(H5Oopen(file_, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!obj.valid()) throw std::runtime_error("HDF5: no object " + object);
  put_number_attribute(obj, name, value);
}

bool H5Writer::exists(const std::string& object) const {
  std::lock_guard lock(hdf5_mutex());
  return path_exists(file_, object);
}

void H5Writer::commit() {
  std::lock_guard lock(hdf5_mutex());
  if (committed_) return;
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush " + partial_.string());
  close();
  commit_file(partial_, final_);
  committed_ = true;
}

void H5Writer::write_transposed_view(const std::string& view, const std::string& source) {
  std::lock_guard lock(hdf5_mutex());
  if (file_ < 0) throw std::logic_error("H5Writer: file already committed");
  if (!exists(source)) throw std::invalid_argument("H5Writer::write_transposed_view: no dataset " + source);
  Handle src(H5Dopen2(file_, source.c_str(), H5P_DEFAULT), H5Dclose);
  Handle src_space(H5Dget_space(src), H5Sclose);
  hsize_t dims[2] = {0, 0};
  if (H5Sget_simple_extent_ndims(src_space) != 2)
    throw std::invalid_argument("H5Writer::write_transposed_view: " + source + " is not 2D");
  H5Sget_simple_extent_dims(src_space, dims, nullptr);
  const hsize_t swapped[2] = {dims[1], dims[0]};
  Handle space(H5Screate_simple(2, swapped, nullptr), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  // Source row r (1 × cols) fills view column r (cols × 1), element by element.
  for (hsize_t r = 0; r < dims[0]; ++r) {
    const hsize_t view_start[2] = {0, r}, view_count[2] = {dims[1], 1};
    const hsize_t row_start[2] = {r, 0}, row_count[2] = {1, dims[1]};
    check(H5Sselect_hyperslab(space, H5S_SELECT_SET, view_start, nullptr, view_count, nullptr), "view selection");
    check(H5Sselect_hyperslab(src_space, H5S_SELECT_SET, row_start, nullptr, row_count, nullptr), "row selection");
    check(H5Pset_virtual(dcpl, space, ".", source.c_str(), src_space), "virtual mapping of " + view);
  }
  check(H5Sselect_all(space), "view extent");
  Handle g(group(view), H5Oclose);
  const auto name = split(view).second;
  if (H5Lexists(g, name.c_str(), H5P_DEFAULT) > 0) check(H5Ldelete(g, name.c_str(), H5P_DEFAULT), "replace " + view);
  Handle ds(H5Dcreate2(g, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) throw std::runtime_error("HDF5: cannot create view " + view);
  put_string_attribute(ds, "description", "view of " + source + " with its axes swapped (no copy)");
}

std::unique_lock<std::recursive_mutex> lock_hdf5() {
  std::unique_lock lock(hdf5_mutex());
  silence_hdf5();
  return lock;
}

// ---------------------------------------------------------------- reader ---

H5Reader::H5Reader(const std::filesystem::path& path) : path_(path) {
  std::lock_guard lock(hdf5_mutex());
  silence_hdf5();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(fmt::format("{}: no such file", path.string()));
  if (H5Fis_hdf5(path.c_str()) <= 0) throw InputError(fmt::format("{}: not an HDF5 file", path.string()));
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) throw InputError(fmt::format("{}: cannot open HDF5 file", path.string()));
}

H5Reader::~H5Reader() {
  std::lock_guard lock(hdf5_mutex());
  if (file_ >= 0) H5Fclose(file_);
}

bool H5Reader::exists(const std::string& path) const {
  std::lock_guard lock(hdf5_mutex());
  return path_exists(file_, path);
}

std::vector<std::size_t> H5Reader::shape(const std::string& dataset) const {
  std::lock_guard lock(hdf5_mutex());
  if (!exists(dataset)) throw InputError(fmt::format("{}: no dataset '{}'", path_.string(), dataset));
  Handle ds(H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) throw InputError(fmt::format("{}: '{}' is not a dataset", path_.string(), dataset));
  Handle space(H5Dget_space(ds), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  return {dims.begin(), dims.end()};
}

std::vector<double> H5Reader::read_series(const std::string& dataset) const {
  std::lock_guard lock(hdf5_mutex());
  const auto dims = shape(dataset);
  std::size_t n = 1;
  for (auto d : dims) n *= d;
  std::vector<double> out(n);
  Handle ds(H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw InputError(fmt::format("{}: cannot read '{}' as numbers", path_.string(), dataset));
  return out;
}

double H5Reader::read_scalar(const std::string& dataset) const {
  std::lock_guard lock(hdf5_mutex());
  auto v = read_series(dataset);
  if (v.size() != 1) throw InputError(fmt::format("{}: '{}' is not a scalar", path_.string(), dataset));
  return v[0];
}

RealField H5Reader::read_field(const std::string& dataset) const {
  std::lock_guard lock(hdf5_mutex());
  const auto dims = shape(dataset);
  if (dims.size() != 2 || dims[0] < 1 || dims[1] < 1)
    throw InputError(fmt::format("{}: '{}' is not a 2D field (rank {})", path_.string(), dataset, dims.size()));
  Handle ds(H5Dopen2(file_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  auto attr_or = [&](const char* name, double fallback) {
    if (H5Aexists(ds, name) <= 0) return fallback;
    Handle a(H5Aopen(ds, name, H5P_DEFAULT), H5Aclose);
    double v = fallback;
    H5Aread(a, H5T_NATIVE_DOUBLE, &v);
    return v;
  };
  RealField f(Grid2D(dims[0], dims[1], attr_or("lx", 1.0), attr_or("ly", 1.0)));
  if (H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, f.data()) < 0)
    throw InputError(fmt::format("{}: cannot read '{}' as numbers", path_.string(), dataset));
  return f;
}

std::string H5Reader::string_attribute(const std::string& object, const std::string& name) const {
  std::lock_guard lock(hdf5_mutex());
  Handle obj(H5Oopen(file_, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!obj.valid() || H5Aexists(obj, name.c_str()) <= 0)
    throw InputError(fmt::format("{}: no attribute '{}' on '{}'", path_.string(), name, object));
  Handle attr(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attr), H5Tclose);
  if (H5Tget_class(type) != H5T_STRING)
    throw InputError(fmt::format("{}: attribute '{}' on '{}' is not a string", path_.string(), name, object));
  std::string out(H5Tget_size(type), '\0');
  Handle mem(H5Tcopy(type), H5Tclose);
  check(H5Aread(attr, mem, out.data()), "read attribute " + name);
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

double H5Reader::number_attribute(const std::string& object, const std::string& name) const {
  std::lock_guard lock(hdf5_mutex());
  Handle obj(H5Oopen(file_, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!obj.valid() || H5Aexists(obj, name.c_str()) <= 0)
    throw InputError(fmt::format("{}: no attribute '{}' on '{}'", path_.string(), name, object));
  Handle attr(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose);
  double v = 0.0;
  check(H5Aread(attr, H5T_NATIVE_DOUBLE, &v), "read attribute " + name);
  return v;
}

}  // namespace wearscale
