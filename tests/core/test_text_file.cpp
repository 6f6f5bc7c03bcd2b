// Text inputs are read whole only when they are regular files within a size
// bound; a UTF-8 byte-order mark is dropped. Memory sizes read and print.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include "input_error_of.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/text_file.hpp"

using namespace wearscale;
namespace fs = std::filesystem;
using ::testing::HasSubstr;

TEST(TextFile, DevicesFoldersAndOversizedFilesAreRefusedNamingThem) {
  EXPECT_THAT(input_error_of([] { read_text_file("/dev/zero", "case file", 1 << 20); }),
              HasSubstr("/dev/zero: not a regular file"));
  EXPECT_THAT(input_error_of([] { read_text_file("/tmp", "case file", 1 << 20); }), HasSubstr("is a directory"));
  EXPECT_THAT(input_error_of([] { read_text_file("/nonexistent.toml", "case file", 1 << 20); }),
              HasSubstr("no such case file"));
  const auto big = fs::temp_directory_path() / ("wearscale_text_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(big) << std::string(5000, 'x');
  EXPECT_THAT(input_error_of([&] { read_text_file(big, "strength table", 4096); }),
              HasSubstr("4.88 KiB, larger than a strength table may be (4 KiB at most)"));
  fs::remove(big);
}

TEST(TextFile, AByteOrderMarkIsDropped) {
  const auto file = fs::temp_directory_path() / ("wearscale_bom_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(file, std::ios::binary) << "\xEF\xBB\xBFpressure_GPa,x\n";
  EXPECT_EQ(read_text_file(file, "table", 1 << 20), "pressure_GPa,x\n");
  EXPECT_EQ(strip_utf8_bom("no mark"), "no mark");
  fs::remove(file);
}

TEST(MemoryLimit, SizesReadAndPrintAndAnImpossibleOneIsRefused) {
  EXPECT_EQ(parse_bytes("4 GiB"), 4.0 * 1073741824.0);
  EXPECT_EQ(parse_bytes("500 MB"), 5e8);
  EXPECT_EQ(parse_bytes("2e9"), 2e9);
  EXPECT_LT(parse_bytes("lots"), 0.0);
  EXPECT_EQ(format_bytes(1536.0), "1.5 KiB");
  EXPECT_EQ(format_bytes(320e9), "298 GiB");
  EXPECT_GT(memory_limit().bytes, 1e6);
  EXPECT_NO_THROW(require_memory(1e6, "a small grid"));
  EXPECT_THAT(input_error_of([] { require_memory(1e30, "a grid of 10^29 points", "give a smaller grid"); }),
              HasSubstr("a grid of 10^29 points needs"));
  EXPECT_THAT(input_error_of([] { require_memory(std::nan(""), "x"); }), HasSubstr("x needs nan B"));
}
