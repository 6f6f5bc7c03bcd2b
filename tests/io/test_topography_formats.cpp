// Measured topographies from instruments' files, each written here to its
// published layout: the heights land at the right (x_i, y_j), in metres,
// with the physical size, units and missing points the file gives; damaged
// or hostile files are refused with a message, never a crash.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <hdf5.h>
#include <openssl/evp.h>
#include <unistd.h>
#include <zip.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/topography_io.hpp"
#include "scratch_dir.hpp"

using namespace wearscale;
using namespace wearscale::bem;
namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {

fs::path scratch(const std::string& name) {
  static const ScratchDir dir("wearscale_formats_");
  return dir.file(name);
}

fs::path write_file(const std::string& name, const std::string& bytes) {
  const auto p = scratch(name);
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

// The surface every format carries: 6 × 4 points (nx ≠ ny), h(x_i, y_j) tells i and j apart.
constexpr std::size_t NX = 6, NY = 4;
double height(std::size_t i, std::size_t j) { return 1e-7 * (static_cast<double>(i) + 10.0 * static_cast<double>(j)) - 1.3e-6; }

// Little- (or big-) endian bytes.
struct Out {
  std::string b;
  bool big = false;
  template <class T>
  Out& put(T v) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &v, sizeof(T));
    for (std::size_t k = 0; k < sizeof(T); ++k) b += static_cast<char>(raw[big ? sizeof(T) - 1 - k : k]);
    return *this;
  }
  Out& text(const std::string& s) { return b += s, *this; }
  Out& cstr(const std::string& s) { return b += s, b += '\0', *this; }
  Out& fixed(const std::string& s, std::size_t n) { return b += s.substr(0, n) + std::string(n - std::min(n, s.size()), ' '), *this; }
  Out& zeros(std::size_t n) { return b += std::string(n, '\0'), *this; }
};

std::string rejection(const fs::path& file, const TopographyOptions& o = {}) {
  try {
    read_measured_topography(file, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

void expect_surface(const MeasuredTopography& t, double lx, double ly, double tolerance, const std::string& format,
                    std::function<bool(std::size_t, std::size_t)> skip = {}) {
  ASSERT_EQ(t.heights.grid().nx, NX);
  ASSERT_EQ(t.heights.grid().ny, NY);
  EXPECT_DOUBLE_EQ(t.heights.grid().lx, lx);
  EXPECT_DOUBLE_EQ(t.heights.grid().ly, ly);
  EXPECT_EQ(t.format, format);
  for (std::size_t i = 0; i < NX; ++i)
    for (std::size_t j = 0; j < NY; ++j)
      if (!skip || !skip(i, j)) {
        EXPECT_NEAR(t.heights(i, j), height(i, j), tolerance) << "at x index " << i << ", y index " << j;
      }
}

// Every prefix of `bytes` and every byte flipped: refused or read, never a crash.
void survives_damage(const std::string& name, const std::string& bytes) {
  TopographyOptions o;
  o.max_points = 1 << 16;
  o.missing = MissingPoints::Fill;
  std::size_t refused = 0;
  for (std::size_t n = 0; n < bytes.size(); n += std::max<std::size_t>(1, bytes.size() / 300)) {
    try {
      parse_measured_topography(std::string_view(bytes).substr(0, n), name, o);
    } catch (const InputError&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 0u);
  for (std::size_t k = 0; k < bytes.size(); k += std::max<std::size_t>(1, bytes.size() / 400)) {
    std::string damaged = bytes;
    damaged[k] = static_cast<char>(damaged[k] ^ 0xA5);
    try {
      const auto t = parse_measured_topography(damaged, name, o);
      for (double v : t.heights) ASSERT_TRUE(std::isfinite(v)) << "byte " << k;
    } catch (const InputError&) {
    }
  }
}

// ------------------------------------------------------------------- X3P ---

std::string md5_hex(const std::string& data) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int n = 0;
  EVP_Digest(data.data(), data.size(), digest, &n, EVP_md5(), nullptr);
  std::string hex;
  for (unsigned k = 0; k < n; ++k) hex += fmt::format("{:02X}", digest[k]);
  return hex;
}

std::string zip_of(const std::vector<std::pair<std::string, std::string>>& entries) {
  const auto path = scratch("archive.zip");
  fs::remove(path);
  int error = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  std::vector<std::string> keep;
  keep.reserve(entries.size());
  for (const auto& [name, content] : entries) {
    keep.push_back(content);
    zip_source_t* s = zip_source_buffer(z, keep.back().data(), keep.back().size(), 0);
    zip_file_add(z, name.c_str(), s, ZIP_FL_OVERWRITE);
  }
  zip_close(z);
  std::stringstream bytes;
  bytes << std::ifstream(path, std::ios::binary).rdbuf();
  return bytes.str();
}

struct X3p {
  std::string type = "D";  // CZ DataType
  double dx = 2.5e-6, dy = 4e-6, z_increment = 1.0, z_offset = 0.0;
  bool valid_file = true, inline_list = false, feature_sur = true;
  std::string md5;  // empty: the right one
  std::vector<std::pair<std::size_t, std::size_t>> invalid = {{4, 1}};

  std::string data() const {
    Out o;
    for (std::size_t j = 0; j < NY; ++j)
      for (std::size_t i = 0; i < NX; ++i) {
        const double h = height(i, j);
        if (type == "D") o.put(h);
        else if (type == "F") o.put(static_cast<float>(h));
        else if (type == "I") o.put(static_cast<std::int16_t>(std::lround((h - z_offset) / z_increment)));
        else o.put(static_cast<std::int32_t>(std::lround((h - z_offset) / z_increment)));
      }
    return o.b;
  }
  std::string bytes() const {
    const std::string points = data();
    std::string valid((NX * NY + 7) / 8, '\xff');
    for (const auto& [i, j] : invalid) {
      const std::size_t k = j * NX + i;  // x fastest
      valid[k / 8] = static_cast<char>(valid[k / 8] & ~(1 << (k % 8)));
    }
    std::string list;
    if (inline_list)
      for (std::size_t j = 0; j < NY; ++j)
        for (std::size_t i = 0; i < NX; ++i)
          list += std::find(invalid.begin(), invalid.end(), std::pair{i, j}) != invalid.end()
                      ? "<Datum/>"
                      : fmt::format("<Datum>{:.17g}</Datum>", height(i, j));
    const std::string record3 =
        inline_list ? "<DataList>" + list + "</DataList>"
                    : fmt::format("<DataLink><PointDataLink>bindata/data.bin</PointDataLink>"
                                  "<MD5ChecksumPointData>{}</MD5ChecksumPointData>{}</DataLink>",
                                  md5.empty() ? md5_hex(points) : md5,
                                  valid_file ? "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>" : "");
    const std::string xml = fmt::format(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">\n"
        "<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>{}</FeatureType><Axes>\n"
        "<CX><AxisType>I</AxisType><DataType>D</DataType><Increment>{:.17g}</Increment><Offset>0</Offset></CX>\n"
        "<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>{:.17g}</Increment><Offset>0</Offset></CY>\n"
        "<CZ><AxisType>A</AxisType><DataType>{}</DataType><Increment>{:.17g}</Increment><Offset>{:.17g}</Offset></CZ>\n"
        "</Axes></Record1>\n"
        "<Record2><Date>2024-01-01T00:00:00</Date><Instrument><Manufacturer>wearscale test</Manufacturer>"
        "<Model>none</Model><Serial>0</Serial><Version>1</Version></Instrument><CalibrationDate>2024-01-01T00:00:00"
        "</CalibrationDate><ProbingSystem><Type>NonContacting</Type><Identification>test</Identification>"
        "</ProbingSystem><Comment>written by test_topography_formats</Comment></Record2>\n"
        "<Record3><MatrixDimension><SizeX>{}</SizeX><SizeY>{}</SizeY><SizeZ>1</SizeZ></MatrixDimension>{}</Record3>\n"
        "<Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>\n"
        "</p:ISO5436_2>\n",
        feature_sur ? "SUR" : "PRF", dx, dy, type, z_increment, z_offset, NX, NY, record3);
    std::vector<std::pair<std::string, std::string>> entries = {{"main.xml", xml},
                                                                {"md5checksum.hex", md5_hex(xml) + " *main.xml\n"}};
    if (!inline_list) {
      entries.emplace_back("bindata/data.bin", points);
      if (valid_file) entries.emplace_back("bindata/valid.bin", valid);
    }
    return zip_of(entries);
  }
};

}  // namespace

TEST(TopographyFormats, X3pGivesHeightsSizeAndInvalidPoints) {
  const X3p x3p;
  const auto file = write_file("surface.x3p", x3p.bytes());
  EXPECT_THAT(rejection(file), HasSubstr("1 of 24 points"));  // refused unless the user chooses
  EXPECT_THAT(rejection(file), HasSubstr("missing = fill"));
  EXPECT_THAT(rejection(file), HasSubstr("point 4 of line 1"));
  TopographyOptions fill;
  fill.missing = MissingPoints::Fill;
  const auto t = read_measured_topography(file, fill);
  EXPECT_EQ(t.missing, 1u);
  expect_surface(t, NX * 2.5e-6, NY * 4e-6, 0.0, "ISO 25178-72 X3P", [](auto i, auto j) { return i == 4 && j == 1; });
  // The filled point: the mean of its four neighbours' weighted values, inside their range.
  EXPECT_GT(t.heights(4, 1), height(4, 0));
  EXPECT_LT(t.heights(4, 1), height(4, 2));
}

TEST(TopographyFormats, X3pIntegerDataAreScaledByTheirIncrementAndOffset) {
  for (const std::string type : {"I", "L"}) {
    X3p x3p;
    x3p.type = type, x3p.z_increment = 1e-9, x3p.z_offset = -1e-6, x3p.invalid.clear();
    const auto t = read_measured_topography(write_file("int.x3p", x3p.bytes()));
    expect_surface(t, NX * 2.5e-6, NY * 4e-6, 0.51e-9, "ISO 25178-72 X3P");
  }
  X3p floats;
  floats.type = "F", floats.invalid.clear(), floats.valid_file = false;
  expect_surface(read_measured_topography(write_file("float.x3p", floats.bytes())), NX * 2.5e-6, NY * 4e-6, 1e-13,
                 "ISO 25178-72 X3P");
}

TEST(TopographyFormats, X3pInlineDataListMarksEmptyDataMissing) {
  X3p x3p;
  x3p.inline_list = true, x3p.invalid = {{0, 0}, {5, 3}};
  TopographyOptions fill;
  fill.missing = MissingPoints::Fill;
  const auto t = read_measured_topography(write_file("list.x3p", x3p.bytes()), fill);
  EXPECT_EQ(t.missing, 2u);
  expect_surface(t, NX * 2.5e-6, NY * 4e-6, 0.0, "ISO 25178-72 X3P",
                 [](auto i, auto j) { return (i == 0 && j == 0) || (i == 5 && j == 3); });
}

TEST(TopographyFormats, DamagedOrForeignX3pFilesAreRefusedSayingWhy) {
  X3p bad_sum;
  bad_sum.md5 = std::string(32, '0');
  EXPECT_THAT(rejection(write_file("sum.x3p", bad_sum.bytes())), HasSubstr("MD5 sum"));
  X3p profile;
  profile.feature_sur = false;
  EXPECT_THAT(rejection(write_file("profile.x3p", profile.bytes())), HasSubstr("FeatureType 'PRF'"));
  EXPECT_THAT(rejection(write_file("other.x3p", zip_of({{"readme.txt", "hello"}}))), HasSubstr("without main.xml"));
  survives_damage("damage.x3p", X3p().bytes());
}

// ------------------------------------------------------------ Gwyddion ---

namespace {

std::string gwy_object(const std::string& type, const std::string& components) {
  Out o;
  o.cstr(type).put(static_cast<std::uint32_t>(components.size())).text(components);
  return o.b;
}

std::string gwy_unit(const std::string& unit) {
  Out c;
  c.cstr("unitstr").put('s').cstr(unit);
  return gwy_object("GwySIUnit", c.b);
}

std::string gwy_field(double xreal, double yreal, const std::string& xy, const std::string& z,
                      const std::function<double(std::size_t, std::size_t)>& value) {
  Out c;
  c.cstr("xres").put('i').put(static_cast<std::int32_t>(NX));
  c.cstr("yres").put('i').put(static_cast<std::int32_t>(NY));
  c.cstr("xreal").put('d').put(xreal);
  c.cstr("yreal").put('d').put(yreal);
  c.cstr("xoff").put('d').put(0.0);
  c.cstr("si_unit_xy").put('o').text(gwy_unit(xy));
  c.cstr("si_unit_z").put('o').text(gwy_unit(z));
  c.cstr("data").put('D').put(static_cast<std::uint32_t>(NX * NY));
  for (std::size_t r = 0; r < NY; ++r)
    for (std::size_t col = 0; col < NX; ++col) c.put(value(col, r));  // rows along y, x fastest
  return gwy_object("GwyDataField", c.b);
}

std::string gwy_file(bool mask) {
  Out c;
  // Channel 0 is a current (A), channel 1 the heights: the reader takes the first of lengths.
  c.cstr("/0/data").put('o').text(gwy_field(1e-5, 1e-5, "m", "A", [](auto, auto) { return 1e-9; }));
  c.cstr("/0/data/title").put('s').cstr("Current");
  c.cstr("/1/data/title").put('s').cstr("Height");
  c.cstr("/1/data").put('o').text(gwy_field(6e-6, 2e-6, "m", "m", height));
  c.cstr("/1/data/visible").put('b').put('\1');
  c.cstr("/meta/list").put('I').put(std::uint32_t{2}).put(std::int32_t{1}).put(std::int32_t{2});
  if (mask)
    c.cstr("/1/mask").put('o').text(gwy_field(6e-6, 2e-6, "m", "", [](auto i, auto j) { return i == 2 && j == 3 ? 1.0 : 0.0; }));
  return "GWYP" + gwy_object("GwyContainer", c.b);
}

std::string gsf_file(const std::string& xy_units, bool nan) {
  std::string header = "Gwyddion Simple Field 1.0\n";
  header += fmt::format("XRes = {}\nYRes = {}\nXReal = {}\nYReal = {}\nXYUnits = {}\nZUnits = m\nTitle = Height\n", NX,
                        NY, xy_units == "m" ? "6e-06" : "6", xy_units == "m" ? "2e-06" : "2", xy_units);
  Out o;
  o.text(header).zeros(4 - header.size() % 4);
  for (std::size_t r = 0; r < NY; ++r)
    for (std::size_t c = 0; c < NX; ++c)
      o.put(nan && c == 1 && r == 2 ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(height(c, r)));
  return o.b;
}

}  // namespace

TEST(TopographyFormats, GwyTakesTheHeightChannelItsSizeAndItsMask) {
  const auto file = write_file("scan.gwy", gwy_file(true));
  EXPECT_THAT(rejection(file), HasSubstr("column 2, row 3 (masked)"));
  TopographyOptions fill;
  fill.missing = MissingPoints::Fill;
  const auto t = read_measured_topography(file, fill);
  EXPECT_EQ(t.missing, 1u);
  expect_surface(t, 6e-6, 2e-6, 0.0, "Gwyddion", [](auto i, auto j) { return i == 2 && j == 3; });
  expect_surface(read_measured_topography(write_file("nomask.gwy", gwy_file(false))), 6e-6, 2e-6, 0.0, "Gwyddion");
  survives_damage("damage.gwy", gwy_file(true));
}

TEST(TopographyFormats, GsfGivesHeightsInItsUnitsAndNanAsMissing) {
  expect_surface(read_measured_topography(write_file("f.gsf", gsf_file("m", false))), 6e-6, 2e-6, 1e-13,
                 "Gwyddion Simple Field");
  expect_surface(read_measured_topography(write_file("um.gsf", gsf_file("um", false))), 6e-6, 2e-6, 1e-13,
                 "Gwyddion Simple Field");
  const auto nan = write_file("nan.gsf", gsf_file("m", true));
  EXPECT_THAT(rejection(nan), HasSubstr("column 1, row 2"));
  TopographyOptions fill;
  fill.missing = MissingPoints::Fill;
  EXPECT_EQ(read_measured_topography(nan, fill).missing, 1u);
  survives_damage("damage.gsf", gsf_file("m", true));
}

TEST(TopographyFormats, GwyddionAsciiExportIsReadWithItsHeaderInAnyLanguage) {
  // Gwyddion's "ASCII data matrix" export: a line per y, x fastest, values in the value unit.
  auto text = [](const char* width, const char* height_key, const char* units) {
    std::string t = fmt::format("# Channel: Height\n# {} 6.000 µm\n# {} 2.000 µm\n# {} m\n", width, height_key, units);
    for (std::size_t r = 0; r < NY; ++r) {
      for (std::size_t c = 0; c < NX; ++c) t += fmt::format("{}{:.17g}", c ? "\t" : "", height(c, r));
      t += "\n";
    }
    return t;
  };
  expect_surface(read_measured_topography(write_file("export.txt", text("Width:", "Height:", "Value units:"))), 6e-6,
                 2e-6, 0.0, "Gwyddion ASCII export");
  expect_surface(read_measured_topography(write_file("export_de.txt", text("Breite:", "Höhe:", "Einheiten:"))), 6e-6,
                 2e-6, 0.0, "Gwyddion ASCII export");
  std::string volts = text("Width:", "Height:", "Value units:");
  volts.replace(volts.find("units: m"), 8, "units: V");
  EXPECT_THAT(rejection(write_file("volts.txt", volts)), HasSubstr("'V', not a unit of length"));
}

// ------------------------------------------------------------ Digital Surf ---

namespace {

// The 512-byte header as Digital Surf lays it out, then the points (x fastest).
std::string sur_file(bool big, std::uint16_t inversion, bool special, std::int32_t bits = 32) {
  const double dz = 1e-3;  // in µm per count
  const std::int32_t zmin = -2000;
  Out h;
  h.big = big;
  h.text("DIGITAL SURF").put(static_cast<std::uint16_t>(big ? 257 : 0)).put(std::uint16_t{1}).put(std::uint16_t{1})
      .put(std::uint16_t{2});
  h.fixed("object", 30).fixed("operator", 30);
  h.put(std::uint16_t{0}).put(std::uint16_t{0}).put(std::uint16_t{0}).put(static_cast<std::uint16_t>(special))
      .put(std::uint16_t{1});
  h.zeros(8).put(static_cast<std::uint16_t>(bits));
  h.put(zmin).put(std::int32_t{2000}).put(static_cast<std::int32_t>(NX)).put(static_cast<std::int32_t>(NY))
      .put(static_cast<std::uint32_t>(NX * NY));
  h.put(1.0f).put(0.5f).put(static_cast<float>(dz));
  h.fixed("X", 16).fixed("Y", 16).fixed("Z", 16);
  for (int k = 0; k < 6; ++k) h.fixed("\xb5m", 16);  // µm in Latin-1
  h.put(1.0f).put(1.0f).put(1.0f).put(std::uint16_t{0}).put(inversion).put(std::uint16_t{0});
  h.zeros(12);
  for (int k = 0; k < 7; ++k) h.put(std::uint16_t{0});
  h.put(0.0f).zeros(10).put(std::uint16_t{5}).put(std::uint16_t{3});  // comment and private zones
  h.zeros(128).put(0.0f).put(0.0f).put(0.0f);
  h.zeros(512 - h.b.size());
  h.text("hello").text("abc");
  for (std::size_t r = 0; r < NY; ++r)
    for (std::size_t c = 0; c < NX; ++c) {
      const std::int32_t v = special && c == 3 && r == 0 ? zmin - 2 : static_cast<std::int32_t>(std::lround(height(c, r) / 1e-6 / dz));
      if (bits == 32) h.put(v);
      else h.put(static_cast<std::int16_t>(v));
    }
  return h.b;
}

}  // namespace

TEST(TopographyFormats, SurGivesHeightsStepsAndUnitsInBothByteOrders) {
  for (const bool big : {false, true})
    for (const std::int32_t bits : {32, 16}) {
      SCOPED_TRACE(fmt::format("big-endian {}, {} bits", big, bits));
      // 1 µm and 0.5 µm steps, heights in counts of 1e-3 µm: to the float32 rounding of that step
      // (|h| ≤ 2.2 µm times 2⁻²⁴, 1.3e-13 m).
      expect_surface(read_measured_topography(write_file("s.sur", sur_file(big, 0, false, bits))), NX * 1e-6,
                     NY * 0.5e-6, 1.5e-13, "Digital Surf");
    }
}

TEST(TopographyFormats, SurInversionAndNonMeasuredPoints) {
  const auto t = read_measured_topography(write_file("flip.sur", sur_file(false, 2, false)));  // z inverted, x mirrored
  for (std::size_t i = 0; i < NX; ++i)
    for (std::size_t j = 0; j < NY; ++j) EXPECT_NEAR(t.heights(NX - 1 - i, j), -height(i, j), 1.5e-13);
  const auto holes = write_file("holes.sur", sur_file(false, 0, true));
  EXPECT_THAT(rejection(holes), HasSubstr("point 3 of line 0 (non-measured)"));
  TopographyOptions fill;
  fill.missing = MissingPoints::Fill;
  EXPECT_EQ(read_measured_topography(holes, fill).missing, 1u);
  survives_damage("damage.sur", sur_file(false, 0, true));
}

// -------------------------------------------------------------------- SDF ---

namespace {
std::string sdf_ascii() {
  std::string t = "aISO-1.0\nManufacID   = wearscale\nCreateDate  = 010120240000\nModDate     = 010120240000\n";
  t += fmt::format("NumPoints   = {}\nNumProfiles = {}\nXscale      = 1.0E-06\nYscale      = 5.0E-07\n", NX, NY);
  t += "Zscale      = 1.0E-09\nZresolution = -1\nCompression = 0\nDataType    = 7\nCheckType   = 0\n*\n";
  for (std::size_t r = 0; r < NY; ++r) {
    for (std::size_t c = 0; c < NX; ++c) t += c == 5 && r == 1 ? " BAD" : fmt::format(" {:.17g}", height(c, r) / 1e-9);
    t += "\n";
  }
  return t + "*\nComment = trailer\n*\n";
}

std::string sdf_binary() {
  Out o;
  o.text("bISO-1.0").fixed("wearscale", 10).fixed("010120240000", 12).fixed("010120240000", 12);
  o.put(static_cast<std::uint16_t>(NX)).put(static_cast<std::uint16_t>(NY)).put(1e-6).put(5e-7).put(1e-9).put(-1.0);
  o.put(std::uint8_t{0}).put(std::uint8_t{5}).put(std::uint8_t{0});  // int16
  for (std::size_t r = 0; r < NY; ++r)
    for (std::size_t c = 0; c < NX; ++c)
      o.put(c == 0 && r == 2 ? std::int16_t{-32768} : static_cast<std::int16_t>(std::lround(height(c, r) / 1e-9)));
  return o.b;
}
}  // namespace

TEST(TopographyFormats, SdfAsciiAndBinaryGiveHeightsStepsAndMissingPoints) {
  TopographyOptions fill;
  fill.missing = MissingPoints::Fill;
  const auto ascii = write_file("a.sdf", sdf_ascii());
  EXPECT_THAT(rejection(ascii), HasSubstr("point 5 of profile 1"));
  const auto a = read_measured_topography(ascii, fill);
  EXPECT_EQ(a.missing, 1u);
  expect_surface(a, NX * 1e-6, NY * 5e-7, 1e-20, "ISO 25178-71 SDF", [](auto i, auto j) { return i == 5 && j == 1; });
  const auto binary = write_file("b.sdf", sdf_binary());
  EXPECT_THAT(rejection(binary), HasSubstr("point 0 of profile 2"));
  const auto b = read_measured_topography(binary, fill);
  expect_surface(b, NX * 1e-6, NY * 5e-7, 0.51e-9, "ISO 25178-71 SDF", [](auto i, auto j) { return i == 0 && j == 2; });
  survives_damage("damage.sdf", sdf_binary());
  survives_damage("damage_ascii.sdf", sdf_ascii());
}

// ------------------------------------------------------------------- DATX ---

namespace {

hid_t vlen_string() {
  const hid_t s = H5Tcopy(H5T_C_S1);
  H5Tset_size(s, H5T_VARIABLE);
  return s;
}

// A converter attribute as Zygo writes it: {Category, BaseUnit, Parameters (vlen of double)}.
void converter(hid_t ds, const char* name, const char* category, const char* unit, std::vector<double> parameters) {
  struct Raw {
    const char* category;
    const char* unit;
    hvl_t parameters;
  } raw{category, unit, {parameters.size(), parameters.data()}};
  const hid_t str = vlen_string(), vlen = H5Tvlen_create(H5T_NATIVE_DOUBLE);
  const hid_t type = H5Tcreate(H5T_COMPOUND, sizeof(Raw));
  H5Tinsert(type, "Category", HOFFSET(Raw, category), str);
  H5Tinsert(type, "BaseUnit", HOFFSET(Raw, unit), str);
  H5Tinsert(type, "Parameters", HOFFSET(Raw, parameters), vlen);
  const hsize_t one = 1;
  const hid_t space = H5Screate_simple(1, &one, nullptr);
  const hid_t attr = H5Acreate2(ds, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attr, type, &raw);
  H5Aclose(attr), H5Sclose(space), H5Tclose(type), H5Tclose(vlen), H5Tclose(str);
}

fs::path datx_file(const std::string& name, bool metadata) {
  const auto path = scratch(name);
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t group = H5Gcreate2(file, "/Measurement", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const hsize_t dims[2] = {NY, NX};  // rows along y
  const hid_t space = H5Screate_simple(2, dims, nullptr);
  const hid_t ds = H5Dcreate2(file, "/Measurement/Surface", H5T_IEEE_F32LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const double no_data = 1.7976931348623157e308;
  std::vector<float> values;
  for (std::size_t r = 0; r < NY; ++r)
    for (std::size_t c = 0; c < NX; ++c)
      values.push_back(c == 1 && r == 1 ? std::numeric_limits<float>::max() : static_cast<float>(height(c, r) * 1e6));
  H5Dwrite(ds, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  converter(ds, "X Converter", "LateralCat", "Pixels", {0.0, 1.5e-6, 0.0, 0.0});
  converter(ds, "Y Converter", "LateralCat", "Pixels", {0.0, 2.5e-6, 0.0, 0.0});
  converter(ds, "Z Converter", "HeightCat", "MicroMeters", {0.0, 6.328e-7, 0.5, 1.0});
  const hsize_t one = 1;
  const hid_t one_space = H5Screate_simple(1, &one, nullptr);
  const hid_t nd = H5Acreate2(ds, "No Data", H5T_IEEE_F64LE, one_space, H5P_DEFAULT, H5P_DEFAULT);
  const double marker = no_data;
  H5Awrite(nd, H5T_NATIVE_DOUBLE, &marker);
  H5Aclose(nd);
  if (metadata) {
    struct Row {
      const char* source;
      const char* link;
      const char* destination;
    };
    const Row rows[] = {{"Root", "Measurement", "{A1}"}, {"{A1}", "Surface", "{B2}"}, {"{B2}", "Path", "/Measurement/Surface"}};
    const hid_t str = vlen_string();
    const hid_t type = H5Tcreate(H5T_COMPOUND, sizeof(Row));
    H5Tinsert(type, "Source", HOFFSET(Row, source), str);
    H5Tinsert(type, "Link", HOFFSET(Row, link), str);
    H5Tinsert(type, "Destination", HOFFSET(Row, destination), str);
    const hsize_t n = 3;
    const hid_t table_space = H5Screate_simple(1, &n, nullptr);
    const hid_t table = H5Dcreate2(file, "/MetaData", type, table_space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(table, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, rows);
    H5Dclose(table), H5Sclose(table_space), H5Tclose(type), H5Tclose(str);
  }
  H5Sclose(one_space), H5Dclose(ds), H5Sclose(space), H5Gclose(group), H5Fclose(file);
  return path;
}

}  // namespace

TEST(TopographyFormats, DatxGivesHeightsStepsUnitsAndNoData) {
  // Written float32 in µm, with float32's max marking the one point without data.
  for (const bool metadata : {true, false}) {
    const auto file = datx_file(metadata ? "m.datx" : "plain.datx", metadata);
    EXPECT_THAT(rejection(file), HasSubstr("column 1, row 1 (no data)"));
    TopographyOptions fill;
    fill.missing = MissingPoints::Fill;
    const auto t = read_measured_topography(file, fill);
    EXPECT_EQ(t.missing, 1u);
    expect_surface(t, NX * 1.5e-6, NY * 2.5e-6, 1e-13, "Zygo datx", [](auto i, auto j) { return i == 1 && j == 1; });
  }
}

// ------------------------------------------------------------ dispatching ---

TEST(TopographyFormats, UnsupportedFormatsSayWhichFormatsAreRead) {
  const std::string plu = rejection(write_file("scan.plu", std::string("\x01\x02\x00\x00 sensofar", 13)));
  EXPECT_THAT(plu, HasSubstr("Sensofar (.plu) is not supported"));
  EXPECT_THAT(plu, HasSubstr("ISO 25178-72 X3P (.x3p)"));
  EXPECT_THAT(plu, HasSubstr("Zygo (.datx)"));
  const std::string blob = rejection(write_file("blob.bin", std::string("\x7f\x00\x13\x37 binary", 12)));
  EXPECT_THAT(blob, HasSubstr("not a topography format wearscale recognises"));
  EXPECT_THAT(blob, HasSubstr("Digital Surf (.sur)"));
}

TEST(TopographyFormats, TheContentDecidesNotTheExtension) {
  expect_surface(read_measured_topography(write_file("renamed.dat.txt", gsf_file("m", false))), 6e-6, 2e-6, 1e-13,
                 "Gwyddion Simple Field");
  const auto datx = datx_file("zygo.datx", true), renamed = scratch("zygo.h5");
  fs::copy_file(datx, renamed, fs::copy_options::overwrite_existing);
  TopographyOptions fill;
  fill.missing = MissingPoints::Fill;
  EXPECT_EQ(read_measured_topography(renamed, fill).format, "Zygo datx");
}

TEST(TopographyFormats, HostileHeadersCannotMakeTheReaderAllocateMoreThanAllowed) {
  // A binary SDF header claiming 65535 × 65535 int16 values with none present.
  Out o;
  o.text("bISO-1.0").fixed("x", 10).fixed("0", 12).fixed("0", 12).put(std::uint16_t{65535}).put(std::uint16_t{65535});
  o.put(1e-6).put(1e-6).put(1e-9).put(0.0).put(std::uint8_t{0}).put(std::uint8_t{5}).put(std::uint8_t{0});
  EXPECT_THAT(rejection(write_file("huge.sdf", o.b)), HasSubstr("ends before"));
  TopographyOptions small;
  small.max_points = 16;
  EXPECT_THAT(rejection(write_file("x.gwy", gwy_file(false)), small), HasSubstr("larger than allowed"));
}
