#pragma once
// HDF5 files as other tools write them (h5py, MATLAB, a damaged copy), made
// with the HDF5 C API: datasets of any type and shape, attributes that are
// arrays, variable-length strings or of the wrong type. For reader tests.
#include <hdf5.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace h5fixture {

class File {
 public:
  explicit File(const std::filesystem::path& path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
    id_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (id_ < 0) throw std::runtime_error("h5fixture: cannot create " + path.string());
  }
  ~File() { H5Fclose(id_); }
  File(const File&) = delete;
  File& operator=(const File&) = delete;

  /// A group (and its parents).
  void group(const std::string& path) {
    std::string walked;
    for (std::size_t start = 1; start <= path.size();) {
      auto end = path.find('/', start);
      if (end == std::string::npos) end = path.size();
      walked = path.substr(0, end);
      if (H5Lexists(id_, walked.c_str(), H5P_DEFAULT) <= 0) H5Gclose(H5Gcreate2(id_, walked.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
      start = end + 1;
    }
  }

  /// A dataset of `dims` written from doubles converted to `file_type`
  /// (H5T_IEEE_F64LE, H5T_IEEE_F32LE, H5T_STD_I32LE…); `values` may be empty
  /// (nothing written: a declared, unwritten, chunked dataset).
  void dataset(const std::string& path, const std::vector<hsize_t>& dims, const std::vector<double>& values,
               hid_t file_type = H5T_IEEE_F64LE) {
    parent_of(path);
    const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    if (values.empty()) {
      std::vector<hsize_t> chunk(dims.size(), 16);
      H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data());
    }
    const hid_t ds = H5Dcreate2(id_, path.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    if (!values.empty()) H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(ds);
    H5Pclose(dcpl);
    H5Sclose(space);
  }

  /// A numeric attribute holding `values` (one value: a scalar, unless `as_array`).
  void number_attribute(const std::string& object, const std::string& name, const std::vector<double>& values,
                        bool as_array = false, hid_t file_type = H5T_IEEE_F64LE) {
    const hid_t obj = H5Oopen(id_, object.c_str(), H5P_DEFAULT);
    const hsize_t n = values.size();
    const hid_t space = values.size() == 1 && !as_array ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr);
    const hid_t a = H5Acreate2(obj, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_DOUBLE, values.data());
    H5Aclose(a);
    H5Sclose(space);
    H5Oclose(obj);
  }

  /// A string attribute: variable length (h5py's default for str) or fixed.
  void string_attribute(const std::string& object, const std::string& name, const std::string& value,
                        bool variable_length = true) {
    const hid_t obj = H5Oopen(id_, object.c_str(), H5P_DEFAULT);
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, variable_length ? H5T_VARIABLE : std::max<std::size_t>(1, value.size()));
    H5Tset_cset(type, H5T_CSET_UTF8);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
    if (variable_length) {
      const char* p = value.c_str();
      H5Awrite(a, type, &p);
    } else {
      H5Awrite(a, type, value.c_str());
    }
    H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
    H5Oclose(obj);
  }

 private:
  void parent_of(const std::string& path) {
    const auto slash = path.rfind('/');
    if (slash != std::string::npos && slash > 0) group(path.substr(0, slash));
  }
  hid_t id_ = -1;
};

}  // namespace h5fixture
