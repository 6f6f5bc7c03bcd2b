// Zygo .datx (Mx): an HDF5 file whose /MetaData table (Source, Link,
// Destination) leads from "Root" through "Measurement" and "Surface" to the
// path of the surface dataset (commonly /Measurement/Surface; older files
// keep it under /Data/Surface). The dataset holds rows along y with x
// fastest; its attributes give the lateral steps ("X Converter", "Y
// Converter": parameter 1 in metres per pixel), the unit of the values
// ("Z Converter" base unit, else "Unit": NanoMeters, MicroMeters, …, or
// Fringes with the wavelength, scale and obliquity factors as parameters
// 1–3) and the value of points without data ("No Data").
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "topography_formats.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale::bem::formats {

namespace {

class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// One member of a compound type (or the whole type) as text or as numbers,
// whatever the file's string or number representation.
struct Member {
  std::string text;
  std::vector<double> numbers;
};

// Reads member `name` of every element of a compound attribute or dataset
// (`read` reads into a buffer of the given memory type).
std::vector<Member> read_member(hid_t file_type, std::size_t count, const char* name,
                                const std::function<herr_t(hid_t, void*)>& read) {
  std::vector<Member> out;
  if (H5Tget_class(file_type) != H5T_COMPOUND) return out;
  const int index = H5Tget_member_index(file_type, name);
  if (index < 0) return out;
  Id member(H5Tget_member_type(file_type, static_cast<unsigned>(index)), H5Tclose);
  const H5T_class_t cls = H5Tget_class(member);
  if (cls == H5T_STRING) {
    const bool variable = H5Tis_variable_str(member) > 0;
    Id string(H5Tcopy(H5T_C_S1), H5Tclose);
    const std::size_t width = variable ? sizeof(char*) : H5Tget_size(member);
    H5Tset_size(string, variable ? H5T_VARIABLE : width);
    Id mem(H5Tcreate(H5T_COMPOUND, width), H5Tclose);
    H5Tinsert(mem, name, 0, string);
    std::vector<char> buffer(width * count + 1, '\0');
    if (read(mem, buffer.data()) < 0) return out;
    for (std::size_t k = 0; k < count; ++k) {
      if (variable) {
        char* s = nullptr;
        std::memcpy(&s, buffer.data() + k * width, sizeof s);
        out.push_back({s != nullptr ? std::string(s) : std::string(), {}});
        H5free_memory(s);
      } else {
        const char* s = buffer.data() + k * width;
        out.push_back({std::string(s, strnlen(s, width)), {}});
      }
    }
  } else if (cls == H5T_VLEN) {
    Id vlen(H5Tvlen_create(H5T_NATIVE_DOUBLE), H5Tclose);
    Id mem(H5Tcreate(H5T_COMPOUND, sizeof(hvl_t)), H5Tclose);
    H5Tinsert(mem, name, 0, vlen);
    std::vector<hvl_t> buffer(count);
    if (read(mem, buffer.data()) < 0) return out;
    for (const auto& v : buffer) {
      const auto* p = static_cast<const double*>(v.p);
      out.push_back({{}, std::vector<double>(p, p + (p != nullptr ? v.len : 0))});
      H5free_memory(v.p);
    }
  } else if (cls == H5T_ARRAY || cls == H5T_FLOAT || cls == H5T_INTEGER) {
    std::size_t n = 1;
    Id mem_member(cls == H5T_ARRAY ? [&] {
      const int rank = H5Tget_array_ndims(member);
      std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
      if (rank > 0) H5Tget_array_dims2(member, dims.data());
      for (auto d : dims) n *= static_cast<std::size_t>(d);
      return H5Tarray_create2(H5T_NATIVE_DOUBLE, static_cast<unsigned>(dims.size()), dims.data());
    }() : H5Tcopy(H5T_NATIVE_DOUBLE), H5Tclose);
    if (n > (1u << 20)) return out;
    Id mem(H5Tcreate(H5T_COMPOUND, n * sizeof(double)), H5Tclose);
    H5Tinsert(mem, name, 0, mem_member);
    std::vector<double> buffer(n * count);
    if (read(mem, buffer.data()) < 0) return out;
    for (std::size_t k = 0; k < count; ++k)
      out.push_back({{}, std::vector<double>(buffer.begin() + static_cast<long>(k * n),
                                             buffer.begin() + static_cast<long>((k + 1) * n))});
  }
  return out;
}

std::size_t elements(hid_t space) {
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

// `attribute` of `object`, open, when it exists and holds 1 to 16 elements:
// `use(attr, type, count)` reads it.
template <class Use>
std::optional<Member> with_small_attribute(hid_t object, const char* attribute, Use&& use) {
  if (H5Aexists(object, attribute) <= 0) return std::nullopt;
  Id attr(H5Aopen(object, attribute, H5P_DEFAULT), H5Aclose);
  Id type(H5Aget_type(attr), H5Tclose);
  Id space(H5Aget_space(attr), H5Sclose);
  const std::size_t n = elements(space);
  if (n == 0 || n > 16) return std::nullopt;
  return use(attr, type, n);
}

std::optional<Member> attribute_member(hid_t object, const char* attribute, const char* member) {
  return with_small_attribute(object, attribute, [&](hid_t attr, hid_t type, std::size_t n) -> std::optional<Member> {
    auto read = [&](hid_t mem, void* buf) { return H5Aread(attr, mem, buf); };
    const auto values = read_member(type, n, member, read);
    if (values.empty()) return std::nullopt;
    return values.front();
  });
}

// A plain (non-compound) attribute as text or a number.
std::optional<Member> attribute_value(hid_t object, const char* attribute) {
  return with_small_attribute(object, attribute, [](hid_t attr, hid_t type, std::size_t n) -> std::optional<Member> {
    if (H5Tget_class(type) == H5T_STRING) {
      if (H5Tis_variable_str(type) > 0) {
        Id mem(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(mem, H5T_VARIABLE);
        std::vector<char*> s(n, nullptr);
        if (H5Aread(attr, mem, s.data()) < 0) return std::nullopt;
        Member m{s[0] != nullptr ? s[0] : "", {}};
        for (auto* p : s) H5free_memory(p);
        return m;
      }
      const std::size_t width = H5Tget_size(type);
      if (width == 0 || width > 4096) return std::nullopt;
      std::vector<char> buf(width * n + 1, '\0');
      Id mem(H5Tcopy(type), H5Tclose);
      if (H5Aread(attr, mem, buf.data()) < 0) return std::nullopt;
      return Member{std::string(buf.data(), strnlen(buf.data(), width)), {}};
    }
    if (H5Tget_class(type) == H5T_FLOAT || H5Tget_class(type) == H5T_INTEGER) {
      std::vector<double> v(n);
      if (H5Aread(attr, H5T_NATIVE_DOUBLE, v.data()) < 0) return std::nullopt;
      return Member{{}, v};
    }
    return std::nullopt;
  });
}

bool is_dataset(hid_t file, const std::string& path) {
  if (path.empty() || path.front() != '/') return false;
  std::size_t start = 1;
  while (start <= path.size()) {  // every link on the way must exist
    auto end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    if (H5Lexists(file, path.substr(0, end).c_str(), H5P_DEFAULT) <= 0) return false;
    start = end + 1;
  }
  Id object(H5Oopen(file, path.c_str(), H5P_DEFAULT), H5Oclose);
  return object.valid() && H5Iget_type(object) == H5I_DATASET;
}

// The surface dataset's path: from /MetaData when it leads to one, else the usual places.
std::string surface_path(hid_t file) {
  if (is_dataset(file, "/MetaData")) {
    Id ds(H5Dopen2(file, "/MetaData", H5P_DEFAULT), H5Dclose);
    Id type(H5Dget_type(ds), H5Tclose);
    Id space(H5Dget_space(ds), H5Sclose);
    const std::size_t n = elements(space);
    if (n > 0 && n < 100000) {
      auto read = [&](hid_t mem, void* buf) { return H5Dread(ds, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf); };
      const auto source = read_member(type, n, "Source", read), link = read_member(type, n, "Link", read),
                 destination = read_member(type, n, "Destination", read);
      if (source.size() == n && link.size() == n && destination.size() == n) {
        auto follow = [&](const std::string& from, const std::string& via) -> std::string {
          for (std::size_t k = 0; k < n; ++k)
            if (source[k].text == from && link[k].text == via) return destination[k].text;
          return {};
        };
        const std::string path = follow(follow(follow("Root", "Measurement"), "Surface"), "Path");
        if (is_dataset(file, path)) return path;
      }
    }
  }
  if (is_dataset(file, "/Measurement/Surface")) return "/Measurement/Surface";
  // Older files: the first dataset of /Data/Surface.
  if (H5Lexists(file, "/Data", H5P_DEFAULT) > 0 && H5Lexists(file, "/Data/Surface", H5P_DEFAULT) > 0) {
    std::string found;
    H5Literate_by_name(file, "/Data/Surface", H5_INDEX_NAME, H5_ITER_INC, nullptr,
                       [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
                         *static_cast<std::string*>(data) = std::string("/Data/Surface/") + name;
                         return 1;
                       },
                       &found, H5P_DEFAULT);
    if (is_dataset(file, found)) return found;
  }
  return {};
}

RawTopography read_datx_file(const std::filesystem::path& path, const TopographyOptions& o) {
  const std::string where = path.string();
  auto lock = lock_hdf5();
  if (H5Fis_hdf5(path.c_str()) <= 0) refuse(where, "not an HDF5 file, so not a Zygo .datx");
  Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) refuse(where, "cannot open the HDF5 file");
  const std::string surface = surface_path(file);
  if (surface.empty())
    refuse(where, "no surface dataset (neither /MetaData leading to one, nor /Measurement/Surface or /Data/Surface)");
  Id ds(H5Dopen2(file, surface.c_str(), H5P_DEFAULT), H5Dclose);
  Id space(H5Dget_space(ds), H5Sclose);
  if (H5Sget_simple_extent_ndims(space) != 2) refuse(where, fmt::format("{} is not a 2D dataset", surface));
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  const auto ny = static_cast<std::size_t>(dims[0]), nx = static_cast<std::size_t>(dims[1]);  // rows along y

  // Units: the Z converter's base unit, else the Unit attribute.
  std::string unit;
  std::vector<double> z_parameters;
  if (const auto base = attribute_member(ds, "Z Converter", "BaseUnit")) unit = base->text;
  if (const auto p = attribute_member(ds, "Z Converter", "Parameters")) z_parameters = p->numbers;
  if (unit.empty())
    if (const auto u = attribute_value(ds, "Unit")) unit = u->text;
  double scale = 0.0;
  if (unit == "Fringes") {
    if (z_parameters.size() < 4)
      refuse(where, "heights in Fringes without the wavelength, scale and obliquity factors (Z Converter parameters)");
    scale = z_parameters[1] * z_parameters[2] * z_parameters[3];  // wavelength [m] · scale factor · obliquity
  } else if (const auto m = metres_per(unit)) {
    scale = *m;
  } else {
    refuse(where, fmt::format("the values of {} are in '{}', not a unit of length", surface,
                              unit.empty() ? "no unit" : unit));
  }
  auto step = [&](const char* converter) -> std::optional<double> {
    const auto p = attribute_member(ds, converter, "Parameters");
    if (!p || p->numbers.size() < 2) return std::nullopt;
    const double s = p->numbers[1];
    if (!(std::isfinite(s) && s > 0.0)) refuse(where, fmt::format("the {} gives a step of {} m", converter, s));
    return s;
  };
  const auto dx = step("X Converter"), dy = step("Y Converter");
  const auto no_data = attribute_value(ds, "No Data");

  RawTopography raw;
  raw.where = where;
  raw.format = "Zygo datx";
  raw.allocate(nx, ny, o.max_points);
  std::vector<double> values(raw.height.size());
  if (H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    refuse(where, fmt::format("{} cannot be read as numbers", surface));
  const bool has_marker = no_data && !no_data->numbers.empty();
  const double marker = has_marker ? no_data->numbers[0] : 0.0;
  // A huge marker (Zygo writes the largest double) also marks float32 data at
  // their largest value, and anything above it.
  const bool huge = has_marker && marker >= 1e30;
  const double huge_from = std::min(marker, static_cast<double>(std::numeric_limits<float>::max()));
  for (std::size_t r = 0; r < ny; ++r)
    for (std::size_t c = 0; c < nx; ++c) {
      const double v = values[r * nx + c];
      raw.at(c, r) = v * scale;
      if (std::isnan(v) || (has_marker && v == marker) || (huge && v >= huge_from)) {
        if (raw.missing.empty()) raw.first_missing = fmt::format("column {}, row {} (no data)", c, r);
        raw.mark_missing(c, r);
      }
    }
  if (dx) raw.lx = static_cast<double>(nx) * *dx;
  if (dy) raw.ly = static_cast<double>(ny) * *dy;
  return raw;
}

}  // namespace

RawTopography read_datx(const std::filesystem::path& path, const TopographyOptions& o) {
  // Tried in a child first: a file that crashes HDF5 itself is refused as damaged.
  return guarded_hdf5_read(path, [&] { return read_datx_file(path, o); });
}

}  // namespace wearscale::bem::formats
