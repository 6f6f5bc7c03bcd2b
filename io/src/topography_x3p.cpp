// ISO 25178-72 X3P (ISO 5436-2 XML file format): a ZIP archive (libzip)
// holding main.xml (pugixml) and the point data. Record1 gives the axes —
// CX and CY incremental with their Increment in metres, CZ absolute with its
// DataType (I int16, L int32, F float32, D float64) and, for integers,
// Increment and Offset; Record3 the matrix size and either a DataLink to a
// little-endian binary file (x fastest, then y) with an optional MD5 sum and
// an optional valid-points bit file, or an inline DataList of Datum values
// (empty for an invalid point). Invalid points are also NaN in float data.
#include <cctype>
#include <cmath>
#include <cstring>
#include <iterator>
#include <memory>

#include <fmt/format.h>
#include <openssl/evp.h>
#include <pugixml.hpp>
#include <zip.h>

#include "topography_formats.hpp"

namespace wearscale::bem::formats {

namespace {

// --- The archive ---------------------------------------------------------

class Archive {
 public:
  Archive(std::string_view bytes, std::string where) : where_(std::move(where)) {
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
    if (source != nullptr) {
      archive_ = zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error);
      if (archive_ == nullptr) zip_source_free(source);
    }
    std::string why = zip_error_strerror(&error);
    zip_error_fini(&error);
    if (archive_ == nullptr) refuse(where_, fmt::format("not a readable ZIP archive ({}), so not an X3P file", why));
  }
  ~Archive() {
    if (archive_ != nullptr) zip_discard(archive_);
  }
  Archive(const Archive&) = delete;
  Archive& operator=(const Archive&) = delete;

  bool has(const std::string& name) const { return zip_name_locate(archive_, name.c_str(), 0) >= 0; }

  /// The uncompressed size the archive records for `name`.
  zip_uint64_t size(const std::string& name) const {
    const zip_int64_t index = zip_name_locate(archive_, name.c_str(), 0);
    if (index < 0) refuse(where_, fmt::format("the archive has no '{}'", name));
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat_index(archive_, static_cast<zip_uint64_t>(index), 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE))
      refuse(where_, fmt::format("the size of '{}' in the archive is unknown", name));
    return st.size;
  }

  /// The uncompressed content of `name`, refused unless it holds exactly
  /// `expected` bytes (when given) or at most `limit`.
  std::string read(const std::string& name, std::optional<std::size_t> expected, std::size_t limit) const {
    const zip_uint64_t bytes = size(name);
    const zip_int64_t index = zip_name_locate(archive_, name.c_str(), 0);
    zip_stat_t st;
    zip_stat_init(&st);
    st.size = bytes;
    if (expected && st.size != *expected)
      refuse(where_, fmt::format("'{}' holds {} bytes, the matrix needs {}", name, st.size, *expected));
    if (st.size > limit) refuse(where_, fmt::format("'{}' is larger ({} bytes) than allowed ({})", name, st.size, limit));
    std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> file(zip_fopen_index(archive_, static_cast<zip_uint64_t>(index), 0),
                                                           zip_fclose);
    if (!file) refuse(where_, fmt::format("'{}' cannot be opened in the archive ({})", name, zip_strerror(archive_)));
    std::string out(static_cast<std::size_t>(st.size), '\0');
    std::size_t got = 0;
    while (got < out.size()) {
      const zip_int64_t n = zip_fread(file.get(), out.data() + got, out.size() - got);
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    if (got != out.size())
      refuse(where_, fmt::format("'{}' is damaged in the archive ({} of {} bytes could be read)", name, got, out.size()));
    return out;
  }

 private:
  std::string where_;
  zip_t* archive_ = nullptr;
};

// --- The XML -------------------------------------------------------------

// The child named `local` (any namespace prefix), or an empty node.
pugi::xml_node child(const pugi::xml_node& node, std::string_view local) {
  for (const auto& c : node.children()) {
    std::string_view name = c.name();
    if (const auto colon = name.find(':'); colon != std::string_view::npos) name.remove_prefix(colon + 1);
    if (name == local) return c;
  }
  return {};
}

std::string text_of(const pugi::xml_node& node) {
  std::string_view t = node.child_value();
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
  return std::string(t);
}

struct Axis {
  std::string type, data_type;
  std::optional<double> increment, offset;
};

std::string md5_hex(std::string_view data) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(data.data(), data.size(), digest, &length, EVP_md5(), nullptr) != 1) return {};
  std::string hex;
  for (unsigned int k = 0; k < length; ++k) hex += fmt::format("{:02x}", digest[k]);
  return hex;
}

}  // namespace

RawTopography parse_x3p(std::string_view bytes, const std::string& where, const TopographyOptions& o) {
  const Archive archive(bytes, where);
  if (!archive.has("main.xml")) refuse(where, "a ZIP archive without main.xml: not an X3P file");
  const std::string xml = archive.read("main.xml", std::nullopt, std::size_t(1) << 28);
  pugi::xml_document doc;
  const auto parsed = doc.load_buffer(xml.data(), xml.size());
  if (!parsed) refuse(where, fmt::format("main.xml is not well-formed XML ({} at byte {})", parsed.description(),
                                         parsed.offset));
  const auto root = child(doc, "ISO5436_2");
  if (!root) refuse(where, "main.xml has no ISO5436_2 element");
  const auto record1 = child(root, "Record1"), record3 = child(root, "Record3");
  if (!record1 || !record3) refuse(where, "main.xml lacks Record1 or Record3");
  const std::string feature = text_of(child(record1, "FeatureType"));
  if (feature != "SUR")
    refuse(where, fmt::format("FeatureType '{}' is not an areal surface (SUR); profiles (PRF) and point clouds (PCL) "
                              "are not read", feature));
  auto number = [&](const pugi::xml_node& node, const std::string& what) -> std::optional<double> {
    if (!node) return std::nullopt;
    const std::string t = text_of(node);
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != t.size() || !std::isfinite(v)) refuse(where, fmt::format("{} = '{}' is not a number", what, t));
    return v;
  };
  auto axis = [&](const char* name) {
    const auto node = child(child(record1, "Axes"), name);
    if (!node) refuse(where, fmt::format("Record1 has no axis {}", name));
    return Axis{text_of(child(node, "AxisType")), text_of(child(node, "DataType")),
                number(child(node, "Increment"), std::string(name) + " Increment"),
                number(child(node, "Offset"), std::string(name) + " Offset")};
  };
  const Axis cx = axis("CX"), cy = axis("CY"), cz = axis("CZ");
  for (const auto& [name, a] : {std::pair{"CX", &cx}, std::pair{"CY", &cy}}) {
    if (a->type != "I")
      refuse(where, fmt::format("axis {} is of type '{}'; only incremental axes (I, a regular grid) are read", name,
                                a->type));
    if (!a->increment || !(*a->increment > 0.0))
      refuse(where, fmt::format("axis {} has no positive Increment (the grid step in metres)", name));
  }
  if (cz.type != "A") refuse(where, fmt::format("axis CZ is of type '{}'; allowed: A (absolute heights)", cz.type));
  const double dz = cz.increment.value_or(1.0), z0 = cz.offset.value_or(0.0);

  const auto matrix = child(record3, "MatrixDimension");
  auto size = [&](const char* name) {
    const auto v = number(child(matrix, name), std::string("MatrixDimension ") + name);
    if (!v || !(*v >= 1.0 && *v <= 1e9 && std::floor(*v) == *v))
      refuse(where, fmt::format("MatrixDimension {} is missing or not a positive integer", name));
    return static_cast<std::size_t>(*v);
  };
  const std::size_t nx = size("SizeX"), ny = size("SizeY"), nz = size("SizeZ");
  if (nz != 1) refuse(where, fmt::format("SizeZ = {}: several layers are not read; allowed: 1", nz));

  RawTopography raw;
  raw.where = where;
  raw.format = "ISO 25178-72 X3P";
  const auto points = product(nx, ny);
  if (!points || *points > o.max_points)
    refuse(where, fmt::format("a grid of {} × {} points is larger than allowed (at most {} points)", nx, ny,
                              o.max_points));
  const std::size_t n = *points;
  // The data's size is checked against the matrix before anything is allocated.
  const auto list = child(record3, "DataList");
  const auto link = child(record3, "DataLink");
  if (list) {
    const auto data = static_cast<std::size_t>(std::distance(list.children().begin(), list.children().end()));
    if (data != n) refuse(where, fmt::format("DataList holds {} data, the matrix {} × {}", data, nx, ny));
  } else if (!link) {
    refuse(where, "Record3 has neither a DataLink nor a DataList: no height data");
  }
  std::size_t width = 0;
  const std::string data_file = text_of(child(link, "PointDataLink"));
  if (!list) {
    if (cz.data_type == "I") width = 2;
    else if (cz.data_type == "L") width = 4;
    else if (cz.data_type == "F") width = 4;
    else if (cz.data_type == "D") width = 8;
    else refuse(where, fmt::format("CZ DataType '{}' is not one of I, L, F, D", cz.data_type));
    if (archive.size(data_file) != n * width)
      refuse(where, fmt::format("'{}' holds {} bytes, the {} × {} matrix of type {} needs {}", data_file,
                                archive.size(data_file), nx, ny, cz.data_type, n * width));
  }
  raw.allocate(nx, ny, o.max_points);
  raw.lx = static_cast<double>(nx) * *cx.increment;
  raw.ly = static_cast<double>(ny) * *cy.increment;
  auto invalid = [&](std::size_t k) {
    if (raw.missing.empty()) raw.first_missing = fmt::format("point {} of line {}", k % nx, k / nx);
    raw.mark_missing(k % nx, k / nx);
  };

  if (list) {
    std::size_t k = 0;
    for (const auto& datum : list.children()) {
      const std::string t = text_of(datum);
      if (t.empty()) {
        invalid(k);
      } else {
        const double v = *number(datum, fmt::format("Datum {}", k + 1));
        raw.at(k % nx, k / nx) = v * dz + z0;
      }
      ++k;
    }
    return raw;
  }
  const std::string data = archive.read(data_file, n * width, n * width);
  if (const auto sum = text_of(child(link, "MD5ChecksumPointData")); !sum.empty()) {
    std::string expected = sum;
    for (auto& c : expected) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (md5_hex(data) != expected) refuse(where, fmt::format("the MD5 sum of '{}' does not match main.xml: the file is "
                                                             "damaged", data_file));
  }
  Bytes b(data, where);
  for (std::size_t k = 0; k < n; ++k) {
    double v = 0.0;
    if (cz.data_type == "I") v = b.i16("the point data") * dz + z0;
    else if (cz.data_type == "L") v = b.i32("the point data") * dz + z0;
    else if (cz.data_type == "F") v = b.f32("the point data") * dz + z0;
    else v = b.f64("the point data") * dz + z0;
    raw.at(k % nx, k / nx) = v;
    if (std::isnan(v)) invalid(k);
  }
  if (const auto valid_file = text_of(child(link, "ValidPointsLink")); !valid_file.empty()) {
    const std::string bits = archive.read(valid_file, (n + 7) / 8, (n + 7) / 8);
    for (std::size_t k = 0; k < n; ++k)
      if ((static_cast<unsigned char>(bits[k / 8]) & (1u << (k % 8))) == 0) invalid(k);
  }
  return raw;
}

}  // namespace wearscale::bem::formats
