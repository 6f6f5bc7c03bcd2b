#include "wearscale/io/hdf5_file.hpp"

#include <hdf5.h>

#include <cmath>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/utc_time.hpp"
#include "wearscale/core/version.hpp"
#include "hdf5_lock.hpp"

namespace wearscale {

namespace {

// Debian's serial HDF5 is not thread-safe: every call into it from these
// wrappers holds this lock, so sweeps can run cases on several threads.
using detail::hdf5_mutex;

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

// A string attribute of variable length, UTF-8, a scalar (h5py reads it as a
// str): its text lives in the file's global heap and the object header holds
// a reference, so no text, however long (a case of megabytes), can exceed
// the 64 KiB an attribute may take in an object header.
void put_string_attribute(hid_t obj, const std::string& name, std::string_view value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  check(H5Tset_size(type, H5T_VARIABLE), "string type");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "string charset");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  Handle attr(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) throw std::runtime_error("HDF5: cannot create attribute " + name);
  const std::string text(value);  // a C string: the text up to a NUL, as every reader takes it
  const char* data = text.c_str();
  check(H5Awrite(attr, type, &data), "write attribute " + name);
}

void put_number_attribute(hid_t obj, const std::string& name, hid_t file_type, hid_t memory_type, const void* value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  Handle attr(H5Acreate2(obj, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) throw std::runtime_error("HDF5: cannot create attribute " + name);
  check(H5Awrite(attr, memory_type, value), "write attribute " + name);
}

void put_number_attribute(hid_t obj, const std::string& name, double value) {
  put_number_attribute(obj, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

// A dataset of doubles of shape `dims` (empty: a scalar, shape ()).
void write_dataset(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims, const double* data,
                   std::string_view unit) {
  Handle space(dims.empty() ? H5Screate(H5S_SCALAR)
                            : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
               H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  hsize_t total = 1;
  for (auto d : dims) total *= d;
  if (total >= 4096) {  // compress large fields; chunks of whole rows
    std::vector<hsize_t> chunk = dims;
    chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(dims[0], (1u << 16) / std::max<hsize_t>(1, total / dims[0])));
    check(H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data()), "chunk");
    check(H5Pset_shuffle(dcpl), "shuffle");
    check(H5Pset_deflate(dcpl, 4), "deflate");
    check(H5Pset_fletcher32(dcpl), "checksum");
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

std::string class_name(H5T_class_t c) {
  switch (c) {
    case H5T_INTEGER: return "an integer";
    case H5T_FLOAT: return "a floating-point number";
    case H5T_STRING: return "a string";
    case H5T_COMPOUND: return "a compound (record)";
    case H5T_ENUM: return "an enumeration (e.g. a boolean)";
    case H5T_ARRAY: return "an array type";
    case H5T_VLEN: return "a variable-length sequence";
    case H5T_REFERENCE: return "a reference";
    default: return "an opaque or bit-field value";
  }
}

// Elements of a dataspace: 0 for a null space, the product of the dimensions
// (as a double: a declared size may exceed 2^64 bytes) otherwise.
double element_count(hid_t space, std::vector<hsize_t>* dims = nullptr) {
  const H5S_class_t kind = H5Sget_simple_extent_type(space);
  if (kind == H5S_NULL || kind == H5S_NO_CLASS) return 0.0;
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0 || rank > H5S_MAX_RANK) return std::nan("");
  std::vector<hsize_t> d(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space, d.data(), nullptr);
  double n = 1.0;
  for (auto v : d) n *= static_cast<double>(v);
  if (dims != nullptr) *dims = std::move(d);
  return n;
}

std::string dims_text(const std::vector<hsize_t>& dims) {
  if (dims.empty()) return "a scalar";
  std::string s;
  for (auto d : dims) s += (s.empty() ? "" : " × ") + std::to_string(d);
  return s;
}

// The text of a string attribute that is already open (fixed or variable length, one element).
std::string read_string(hid_t attr, hid_t type, const std::string& where) {
  if (H5Tis_variable_str(type) > 0) {
    Handle mem(H5Tcopy(H5T_C_S1), H5Tclose);
    check(H5Tset_size(mem, H5T_VARIABLE), "string type");
    check(H5Tset_cset(mem, H5Tget_cset(type)), "string charset");
    char* text = nullptr;
    if (H5Aread(attr, mem, &text) < 0) throw InputError(fmt::format("{}: cannot read it as a string", where));
    std::string out = text != nullptr ? std::string(text) : std::string();
    if (text != nullptr) H5free_memory(text);
    return out;
  }
  const std::size_t size = H5Tget_size(type);
  require_memory(static_cast<double>(size), where);
  std::string out(size, '\0');
  Handle mem(H5Tcopy(type), H5Tclose);
  if (size > 0 && H5Aread(attr, mem, out.data()) < 0)
    throw InputError(fmt::format("{}: cannot read it as a string", where));
  const auto end = out.find('\0');
  if (end != std::string::npos) out.resize(end);
  return out;
}

}  // namespace


// ---------------------------------------------------------------- writer ---

H5Writer::H5Writer(std::filesystem::path final_path, Commit mode, H5Storage storage, std::filesystem::path partial)
    : final_(std::move(final_path)), partial_(std::move(partial)), mode_(mode), storage_(storage) {
  std::lock_guard lock(hdf5_mutex());
  silence_hdf5();
  if (!final_.parent_path().empty()) create_output_folder(final_.parent_path());
  if (partial_.empty()) partial_ = partial_path(final_);
  write_temporary_file(partial_, {});  // the folder takes files: checked now, not after the work
  // In memory: HDF5 never writes to disk itself, so a full disk cannot fail
  // inside it (its close would then crash at exit); commit() writes the image.
  // On disk (fields too large for one process's memory): HDF5 writes its
  // metadata only, into space finish_layout() reserves before it closes.
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (storage_ == H5Storage::Memory) check(H5Pset_fapl_core(fapl, std::size_t{1} << 20, 0), "in-memory driver");
  // The default (oldest) file format: HDF5 1.10's image of a file with a
  // checksummed superblock (format 1.8+) carries a wrong checksum.
  file_ = H5Fcreate(partial_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  if (file_ < 0) {
    std::error_code ec;
    std::filesystem::remove(partial_, ec);
    if (storage_ == H5Storage::Disk)  // HDF5 wrote its superblock and failed: the disk
      throw OutputError(fmt::format("HDF5 cannot create {}; {} was not written", partial_.string(), final_.string()));
    throw std::runtime_error("HDF5: cannot create " + partial_.string());
  }
  // Provenance on every file (the mutex is recursive).
  set_attribute("/", "wearscale_version", version());
  set_attribute("/", "created", utc_now());
  if (const std::string rev = git_revision(); !rev.empty()) set_attribute("/", "git_revision", rev);
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

namespace {
// The attributes every field carries beside its values (write_field, reserve_field).
void put_field_attributes(hid_t ds, const Grid2D& grid, std::string_view unit, std::string_view description,
                          std::array<double, 2> origin) {
  if (!unit.empty()) put_string_attribute(ds, "unit", unit);
  put_number_attribute(ds, "lx", grid.lx);
  put_number_attribute(ds, "ly", grid.ly);
  put_number_attribute(ds, "x0", origin[0]);
  put_number_attribute(ds, "y0", origin[1]);
  put_string_attribute(ds, "axes", "x,y");
  if (!description.empty()) put_string_attribute(ds, "description", description);
}
}  // namespace

void H5Writer::write_field(const std::string& path, const RealField& field, std::string_view unit,
                           std::string_view description, std::array<double, 2> origin) {
  std::lock_guard lock(hdf5_mutex());
  if (field.layout() != Layout::Physical) throw std::invalid_argument("H5Writer::write_field: spectral field");
  Handle g(group(path), H5Oclose);
  const auto name = split(path).second;
  write_dataset(g, name, {field.rows(), field.cols()}, field.data(), {});
  Handle ds(H5Dopen2(g, name.c_str(), H5P_DEFAULT), H5Dclose);
  put_field_attributes(ds, field.grid(), unit, description, origin);
}

std::uint64_t H5Writer::reserve_field(const std::string& path, const Grid2D& grid, std::string_view unit,
                                      std::string_view description, std::array<double, 2> origin) {
  std::lock_guard lock(hdf5_mutex());
  if (storage_ != H5Storage::Disk) throw std::logic_error("H5Writer::reserve_field: the file is built in memory");
  Handle g(group(path), H5Oclose);
  const auto name = split(path).second;
  const hsize_t dims[2] = {grid.nx, grid.ny};
  Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  check(H5Pset_layout(dcpl, H5D_CONTIGUOUS), "contiguous layout");
  check(H5Pset_alloc_time(dcpl, H5D_ALLOC_TIME_EARLY), "allocation at creation");
  check(H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER), "no fill");
  Handle ds(H5Dcreate2(g, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose);
  if (!ds.valid()) throw std::runtime_error("HDF5: cannot create dataset " + path);
  const haddr_t offset = H5Dget_offset(ds);
  if (offset == HADDR_UNDEF) throw std::runtime_error("HDF5: no storage allocated for " + path);
  put_field_attributes(ds, grid, unit, description, origin);
  return static_cast<std::uint64_t>(offset);
}

void H5Writer::finish_layout() {
  std::lock_guard lock(hdf5_mutex());
  if (storage_ != H5Storage::Disk) throw std::logic_error("H5Writer::finish_layout: the file is built in memory");
  if (file_ < 0) return;
  hsize_t size = 0;
  check(H5Fget_filesize(file_, &size), "size of " + partial_.string());
  try {
    // The file's extent (its reserved fields included) and room for the
    // metadata HDF5 still writes on closing; it truncates the rest away.
    reserve_space(partial_, static_cast<std::uint64_t>(size) + (std::uint64_t{1} << 20));
  } catch (const OutputError& e) {
    throw OutputError(fmt::format("{}; {} was not written", e.what(), final_.string()));
  }
  if (H5Fclose(file_) < 0) {
    file_ = -1;
    throw OutputError(fmt::format("HDF5 could not close {}; {} was not written", partial_.string(), final_.string()));
  }
  file_ = -1;
}

void H5Writer::hand_over() {
  finish_layout();
  committed_ = true;  // nothing of it left to this writer
}

void H5Writer::write_scalar(const std::string& path, double value, std::string_view unit) {
  std::lock_guard lock(hdf5_mutex());
  Handle g(group(path), H5Oclose);
  write_dataset(g, split(path).second, {}, &value, unit);
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

void H5Writer::set_integer_attribute(const std::string& object, const std::string& name, std::int64_t value) {
  std::lock_guard lock(hdf5_mutex());
  if (!H5Writer::exists(object)) ensure_group(object);
  Handle obj(H5Oopen(file_, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!obj.valid()) throw std::runtime_error("HDF5: no object " + object);
  put_number_attribute(obj, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

bool H5Writer::exists(const std::string& object) const {
  std::lock_guard lock(hdf5_mutex());
  return path_exists(file_, object);
}

void H5Writer::commit() {
  std::lock_guard lock(hdf5_mutex());
  if (committed_) return;
  if (storage_ == H5Storage::Disk) {
    finish_layout();
    try {
      commit_file(partial_, final_, mode_);
    } catch (const OutputError& e) {
      throw OutputError(fmt::format("{}; {} was not written", e.what(), final_.string()));
    }
    committed_ = true;
    return;
  }
  if (file_ < 0) throw std::logic_error("H5Writer: commit after a failed commit");
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush " + partial_.string());
  const ssize_t size = H5Fget_file_image(file_, nullptr, 0);
  if (size < 0) throw std::runtime_error("HDF5: cannot take the image of " + partial_.string());
  std::string image(static_cast<std::size_t>(size), '\0');
  if (H5Fget_file_image(file_, image.data(), image.size()) != size)
    throw std::runtime_error("HDF5: cannot take the image of " + partial_.string());
  close();
  try {
    write_temporary_file(partial_, image);
    commit_file(partial_, final_, mode_);
  } catch (const OutputError& e) {
    throw OutputError(fmt::format("{}; {} was not written", e.what(), final_.string()));
  }
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

H5Reader::H5Reader(const std::filesystem::path& path) : name_(path.string()) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError(fmt::format("{}: no such file", name_));
  if (!std::filesystem::is_regular_file(status))
    throw InputError(fmt::format("{}: not a regular file; expected an HDF5 file", name_));
  std::lock_guard lock(hdf5_mutex());
  silence_hdf5();
  if (H5Fis_hdf5(path.c_str()) <= 0) throw InputError(fmt::format("{}: not an HDF5 file", name_));
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) throw InputError(fmt::format("{}: cannot open HDF5 file (damaged?)", name_));
}

H5Reader H5Reader::from_image(std::string_view bytes, const std::string& name) {
  std::lock_guard lock(hdf5_mutex());
  silence_hdf5();
  H5Reader r;
  r.name_ = name;
  if (bytes.size() < 8) throw InputError(fmt::format("{}: not an HDF5 file", name));
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  check(H5Pset_fapl_core(fapl, std::size_t{1} << 16, 0), "in-memory driver");
  check(H5Pset_file_image(fapl, const_cast<char*>(bytes.data()), bytes.size()), "file image");
  r.file_ = H5Fopen(name.c_str(), H5F_ACC_RDONLY, fapl);
  if (r.file_ < 0) throw InputError(fmt::format("{}: not an HDF5 file, or a damaged one", name));
  return r;
}

void detail::refuse_if_damaged(const std::string& name, double bytes, const std::function<void()>& read) {
  // Seconds a child may take: a hang in HDF5 is a damaged file too.
  const detail::Trial trial = detail::try_in_child(read, 5.0 + bytes / 20e6);
  if (!trial.failure.empty())
    throw InputError(fmt::format("{}: damaged or not what it claims: {}", name, trial.failure));
  if (!trial.input_error.empty()) throw InputError(trial.input_error);
}

H5Reader::H5Reader(H5Reader&& other) noexcept : name_(std::move(other.name_)), file_(other.file_) { other.file_ = -1; }

H5Reader::~H5Reader() {
  std::lock_guard lock(hdf5_mutex());
  if (file_ >= 0) H5Fclose(file_);
}

bool H5Reader::exists(const std::string& path) const {
  std::lock_guard lock(hdf5_mutex());
  return path_exists(file_, path);
}

namespace {

// An open dataset with what its readers check: dimensions, element count and type class.
struct DatasetInfo {
  hid_t id = -1;
  std::vector<hsize_t> dims;
  double count = 0.0;
  H5T_class_t type_class = H5T_NO_CLASS;
  std::size_t type_size = 0;
  std::size_t precision = 0;
};

DatasetInfo inspect(hid_t file, const std::string& file_name, const std::string& dataset) {
  if (!path_exists(file, dataset)) throw InputError(fmt::format("{}: no dataset '{}'", file_name, dataset));
  H5O_info_t info{};
  if (H5Oget_info_by_name(file, dataset.c_str(), &info, H5P_DEFAULT) < 0 || info.type != H5O_TYPE_DATASET)
    throw InputError(fmt::format("{}: '{}' is not a dataset", file_name, dataset));
  DatasetInfo d;
  d.id = H5Dopen2(file, dataset.c_str(), H5P_DEFAULT);
  if (d.id < 0) throw InputError(fmt::format("{}: cannot open dataset '{}' (damaged?)", file_name, dataset));
  Handle space(H5Dget_space(d.id), H5Sclose);
  Handle type(H5Dget_type(d.id), H5Tclose);
  if (!space.valid() || !type.valid()) {
    H5Dclose(d.id);
    throw InputError(fmt::format("{}: cannot read the shape of dataset '{}' (damaged?)", file_name, dataset));
  }
  d.count = element_count(space, &d.dims);
  d.type_class = H5Tget_class(type);
  d.type_size = H5Tget_size(type);
  d.precision = d.type_class == H5T_INTEGER || d.type_class == H5T_FLOAT ? H5Tget_precision(type) : 0;
  if (!std::isfinite(d.count)) {
    H5Dclose(d.id);
    throw InputError(fmt::format("{}: dataset '{}' has a malformed shape", file_name, dataset));
  }
  return d;
}

// The values of a numeric dataset, as doubles, after the memory check.
std::vector<double> read_numbers(const DatasetInfo& d, const std::string& file_name, const std::string& dataset) {
  Handle ds(d.id, H5Dclose);
  if (d.type_class != H5T_INTEGER && d.type_class != H5T_FLOAT)
    throw InputError(fmt::format("{}: dataset '{}' holds {} values, not numbers", file_name, dataset,
                                 class_name(d.type_class)));
  require_memory(d.count * sizeof(double),
                 fmt::format("{}: dataset '{}' ({} values)", file_name, dataset, dims_text(d.dims)));
  std::vector<double> out(static_cast<std::size_t>(d.count));
  if (!out.empty() && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw InputError(fmt::format("{}: cannot read dataset '{}' as numbers (damaged or an unsupported type?)",
                                 file_name, dataset));
  return out;
}

}  // namespace

std::vector<std::size_t> H5Reader::shape(const std::string& dataset) const {
  std::lock_guard lock(hdf5_mutex());
  const DatasetInfo d = inspect(file_, name_, dataset);
  H5Dclose(d.id);
  return {d.dims.begin(), d.dims.end()};
}

std::vector<double> H5Reader::read_series(const std::string& dataset) const {
  std::lock_guard lock(hdf5_mutex());
  return read_numbers(inspect(file_, name_, dataset), name_, dataset);
}

std::vector<double> H5Reader::read_exact(const std::string& dataset) const {
  std::lock_guard lock(hdf5_mutex());
  const DatasetInfo d = inspect(file_, name_, dataset);
  if (d.type_class != H5T_FLOAT || d.type_size != 8 || d.precision != 64 || d.dims.size() > 1) {
    H5Dclose(d.id);
    throw InputError(fmt::format("{}: dataset '{}' is {} of {} ({} bytes each); expected a series of 64-bit floats",
                                 name_, dataset, dims_text(d.dims), class_name(d.type_class), d.type_size));
  }
  return read_numbers(d, name_, dataset);
}

double H5Reader::read_scalar(const std::string& dataset) const {
  std::lock_guard lock(hdf5_mutex());
  auto v = read_series(dataset);
  if (v.size() != 1) throw InputError(fmt::format("{}: '{}' holds {} values, not one", name_, dataset, v.size()));
  return v[0];
}

RealField H5Reader::read_field(const std::string& dataset) const {
  std::lock_guard lock(hdf5_mutex());
  const DatasetInfo d = inspect(file_, name_, dataset);
  if (d.dims.size() != 2 || d.dims[0] < 1 || d.dims[1] < 1) {
    H5Dclose(d.id);
    throw InputError(fmt::format("{}: '{}' is not a 2D field ({})", name_, dataset, dims_text(d.dims)));
  }
  const double lx = number_attribute_if(dataset, "lx").value_or(1.0);
  const double ly = number_attribute_if(dataset, "ly").value_or(1.0);
  const auto values = read_numbers(d, name_, dataset);  // memory checked there, before the field below
  RealField f(Grid2D(d.dims[0], d.dims[1], lx, ly));
  std::copy(values.begin(), values.end(), f.begin());
  return f;
}

long long H5Reader::open_attribute(const std::string& object, const std::string& name, bool required) const {
  if (!path_exists(file_, object)) {
    if (!required) return -1;
    throw InputError(fmt::format("{}: no object '{}' (looking for its attribute '{}')", name_, object, name));
  }
  Handle obj(H5Oopen(file_, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!obj.valid()) throw InputError(fmt::format("{}: cannot open '{}' (damaged?)", name_, object));
  const htri_t present = H5Aexists(obj, name.c_str());
  if (present <= 0) {
    if (!required && present == 0) return -1;
    throw InputError(fmt::format("{}: no attribute '{}' on '{}'", name_, name, object));
  }
  const hid_t attr = H5Aopen(obj, name.c_str(), H5P_DEFAULT);
  if (attr < 0) throw InputError(fmt::format("{}: cannot open attribute '{}' on '{}' (damaged?)", name_, name, object));
  Handle space(H5Aget_space(attr), H5Sclose);
  std::vector<hsize_t> dims;
  const double count = space.valid() ? element_count(space, &dims) : std::nan("");
  if (count != 1.0) {
    H5Aclose(attr);
    throw InputError(fmt::format("{}: attribute '{}' on '{}' holds {} values ({}); allowed: one", name_, name, object,
                                 std::isfinite(count) ? fmt::format("{:g}", count) : "?", dims_text(dims)));
  }
  return attr;
}

std::string H5Reader::string_attribute(const std::string& object, const std::string& name) const {
  std::lock_guard lock(hdf5_mutex());
  { Handle probe(open_attribute(object, name, true), H5Aclose); }  // absent: InputError naming it
  return *string_attribute_if(object, name);
}

std::optional<std::string> H5Reader::string_attribute_if(const std::string& object, const std::string& name) const {
  std::lock_guard lock(hdf5_mutex());
  const hid_t id = open_attribute(object, name, false);
  if (id < 0) return std::nullopt;
  Handle attr(id, H5Aclose);
  Handle type(H5Aget_type(attr), H5Tclose);
  const std::string where = fmt::format("{}: attribute '{}' on '{}'", name_, name, object);
  if (H5Tget_class(type) != H5T_STRING)
    throw InputError(fmt::format("{} is {}, not a string", where, class_name(H5Tget_class(type))));
  return read_string(attr, type, where);
}

std::optional<double> H5Reader::number_attribute_if(const std::string& object, const std::string& name) const {
  std::lock_guard lock(hdf5_mutex());
  const hid_t id = open_attribute(object, name, false);
  if (id < 0) return std::nullopt;
  Handle attr(id, H5Aclose);
  Handle type(H5Aget_type(attr), H5Tclose);
  const H5T_class_t c = H5Tget_class(type);
  const std::string where = fmt::format("{}: attribute '{}' on '{}'", name_, name, object);
  if (c == H5T_STRING) {
    std::string text = read_string(attr, type, where);
    if (text.size() > 40) text = text.substr(0, 40) + "…";
    throw InputError(fmt::format("{} is the string '{}'; allowed: one number", where, text));
  }
  if (c != H5T_INTEGER && c != H5T_FLOAT)
    throw InputError(fmt::format("{} is {}; allowed: one number", where, class_name(c)));
  double v = 0.0;
  if (H5Aread(attr, H5T_NATIVE_DOUBLE, &v) < 0) throw InputError(fmt::format("{}: cannot read it as a number", where));
  return v;
}

double H5Reader::number_attribute(const std::string& object, const std::string& name) const {
  std::lock_guard lock(hdf5_mutex());
  { Handle probe(open_attribute(object, name, true), H5Aclose); }  // absent: InputError naming it
  return *number_attribute_if(object, name);
}

std::int64_t H5Reader::integer_attribute(const std::string& object, const std::string& name) const {
  std::lock_guard lock(hdf5_mutex());
  Handle attr(open_attribute(object, name, true), H5Aclose);
  Handle type(H5Aget_type(attr), H5Tclose);
  const std::string where = fmt::format("{}: attribute '{}' on '{}'", name_, name, object);
  if (H5Tget_class(type) != H5T_INTEGER)
    throw InputError(fmt::format("{} is {}; allowed: one integer", where, class_name(H5Tget_class(type))));
  std::int64_t v = 0;
  if (H5Aread(attr, H5T_NATIVE_INT64, &v) < 0) throw InputError(fmt::format("{}: cannot read it as an integer", where));
  return v;
}

}  // namespace wearscale
