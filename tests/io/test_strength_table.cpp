// Strength tables: the shipped ones load, malformed ones are refused with
// the file and line, and what is written reads back.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <sstream>

#include "h5_fixture.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/shipped_data.hpp"
#include "wearscale/io/strength_table_file.hpp"
#include "scratch_dir.hpp"

using namespace wearscale;
using namespace wearscale::materials;
using ::testing::HasSubstr;

namespace {
const ScratchDir dir_scratch("wearscale_tables_");
const std::filesystem::path dir = dir_scratch.path();

std::filesystem::path write(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

std::string error_of(const std::filesystem::path& p) {
  try {
    read_strength_table(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

// The older form: a '#' provenance line and GPa columns (still read).
const std::string kHeader = "# material: X\npressure_GPa,sigma_max_GPa,sigma_dyn_GPa\n";
}  // namespace

TEST(StrengthTable, ShippedThesisTablesLoadWithTheirSource) {
  const auto si = shipped_table("thesis", "Si");
  EXPECT_EQ(si.material, "Si");
  EXPECT_THAT(si.info("source"), HasSubstr("Fig. 9.18"));
  EXPECT_EQ(si.pressure.back(), 30e9);
  const auto sio2 = shipped_table("thesis", "SiO2");
  EXPECT_EQ(sio2.pressure.back(), 50e9);
  EXPECT_NEAR(sio2.sigma_dyn.front(), 6.3e9, 1e-3);
}

TEST(StrengthTable, ShippedLammpsTablesLoadWithTheirRunSettings) {
  for (const char* m : {"Si", "SiO2"}) {
    const auto t = shipped_table("lammps", m);
    EXPECT_EQ(t.material, m);
    EXPECT_FALSE(t.info("lammps_version").empty()) << m;
    EXPECT_FALSE(t.info("potential").empty()) << m;
  }
}

TEST(StrengthTable, NonMonotonePressureIsRefusedWithTheLine) {
  const auto p = write("nonmonotone.csv", kHeader + "0,1,1\n10,1,1\n5,1,1\n");
  EXPECT_THAT(error_of(p), HasSubstr("nonmonotone.csv:5"));
  EXPECT_THAT(error_of(p), HasSubstr("must not decrease"));
}

TEST(StrengthTable, MissingColumnIsRefused) {
  const auto p = write("nocol.csv", "pressure_Pa,sigma_max_Pa\n0,1\n1,1\n");
  EXPECT_THAT(error_of(p), HasSubstr("missing column 'sigma_dyn_Pa'"));
  EXPECT_THAT(error_of(write("twice.csv", "pressure_Pa,pressure_GPa,sigma_max_Pa,sigma_dyn_Pa\n0,0,1,1\n1,1,1,1\n")),
              HasSubstr("two 'pressure' columns"));
  EXPECT_THAT(error_of(write("badunit.csv", "pressure_bar,sigma_max_Pa,sigma_dyn_Pa\n0,1,1\n1,1,1\n")),
              HasSubstr("missing column 'pressure_Pa'"));
}

TEST(StrengthTable, NaNIsRefusedWithTheLine) {
  EXPECT_THAT(error_of(write("nan.csv", kHeader + "0,1,1\n10,nan,1\n")), HasSubstr("nan.csv:4"));
  EXPECT_THAT(error_of(write("text.csv", kHeader + "0,1,1\n10,strong,1\n")), HasSubstr("'strong' is not a number"));
}

TEST(StrengthTable, NegativeStrengthIsRefusedWithTheLine) {
  const auto msg = error_of(write("neg.csv", kHeader + "0,1,1\n10,1,-2\n"));
  EXPECT_THAT(msg, HasSubstr("neg.csv:4"));
  EXPECT_THAT(msg, HasSubstr("negative strength"));
}

TEST(StrengthTable, RaggedRowsAndDegenerateTablesAreRefused) {
  EXPECT_THAT(error_of(write("ragged.csv", kHeader + "0,1,1\n10,1\n")), HasSubstr("ragged.csv:4"));
  EXPECT_THAT(error_of(write("one.csv", kHeader + "0,1,1\n")), HasSubstr("at least two pressures"));
  EXPECT_THAT(error_of(write("triple.csv", kHeader + "0,1,1\n5,1,1\n5,2,2\n5,3,3\n9,1,1\n")),
              HasSubstr("three times"));
  EXPECT_THAT(error_of(write("edge.csv", kHeader + "0,1,1\n5,1,1\n5,2,2\n")), HasSubstr("both sides"));
  EXPECT_THAT(error_of(dir / "absent.csv"), HasSubstr("no such strength table"));
}

TEST(StrengthTable, WrittenCsvIsOneHeaderInPascalsWithTheProvenanceInItsSidecar) {
  const auto si = shipped_table("thesis", "Si");
  const auto file = dir / "si.csv";
  write_strength_table(file, si);
  std::ifstream in(file);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header, "pressure_Pa,sigma_max_Pa,sigma_dyn_Pa");
  EXPECT_EQ(row, "0.0,1.06e+10,1500000000.0") << "SI: 10.6 GPa is 1.06e10 Pa, written as pandas writes floats";
  std::ifstream side(file.string() + ".json");
  std::stringstream ss;
  ss << side.rdbuf();
  EXPECT_THAT(ss.str(), HasSubstr("\"source: thesis Fig. 9.18a"));
  EXPECT_THAT(ss.str(), HasSubstr("\"sigma_max_Pa\": \"Pa\""));
}

TEST(StrengthTable, TheOlderFormInGigapascalsWithCommentLinesStillReads) {
  const auto old = write("old.csv", "# material: Cu\n# source: by hand\npressure_GPa,sigma_max_GPa,sigma_dyn_GPa\n"
                                    "0,2.5,0.8\n10,3,1.2\n");
  const auto t = read_strength_table(old);
  EXPECT_EQ(t.material, "Cu");
  EXPECT_EQ(t.info("source"), "by hand");
  EXPECT_EQ(t.pressure, (std::vector<double>{0.0, 10e9}));
  EXPECT_DOUBLE_EQ(t.sigma_max[0], 2.5e9);
  // Mixed units per column, MPa too: each column by its own name.
  const auto mixed = read_strength_table(write("mixed.csv", "sigma_dyn_MPa,pressure_Pa,sigma_max_GPa\n800,0,2.5\n"
                                                            "1200,1e10,3\n"));
  EXPECT_DOUBLE_EQ(mixed.sigma_dyn[1], 1.2e9);
  EXPECT_DOUBLE_EQ(mixed.pressure[1], 1e10);
}

TEST(StrengthTable, WrittenTablesReadBackInCsvAndHdf5) {
  const auto si = shipped_table("thesis", "Si");
  for (const char* name : {"copy.csv", "copy.h5"}) {
    write_strength_table(dir / name, si);
    const auto back = read_strength_table(dir / name);
    EXPECT_EQ(back.pressure, si.pressure) << name;
    EXPECT_EQ(back.sigma_max, si.sigma_max) << name;
    EXPECT_EQ(back.sigma_dyn, si.sigma_dyn) << name;
    EXPECT_EQ(back.material, "Si") << name;
    EXPECT_EQ(back.info("source"), si.info("source")) << name;
  }
  std::filesystem::remove_all(dir);
}

// A table found by fuzzing whose global heap (where its variable-length
// strings live) is damaged so that HDF5 1.10 itself crashes reading it: the
// read is tried in a child process first, so the table is refused as
// damaged, naming it, instead of the program dying.
TEST(StrengthTable, AnHdf5TableThatCrashesTheHdf5LibraryIsRefusedAsDamaged) {
  const std::filesystem::path file = std::filesystem::path(WEARSCALE_TEST_DATA) / "hdf5_crash_global_heap.h5";
  try {
    read_strength_table(file);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    // Crashed (a signal), or under AddressSanitizer stopped by its report (exit status 1).
    EXPECT_THAT(e.what(), ::testing::HasSubstr("hdf5_crash_global_heap.h5: damaged or not what it claims: the HDF5 "
                                               "library "));
  }
}

// h5py writes string attributes as variable-length strings, and a column's unit may be GPa.
TEST(StrengthTable, AnHdf5TableFromAnotherToolReadsWithItsUnits) {
  const auto file = std::filesystem::temp_directory_path() / ("wearscale_h5py_" + std::to_string(::getpid()) + ".h5");
  {
    h5fixture::File f(file);
    f.dataset("/strength/pressure", {3}, {0.0, 5.0, 10.0});
    f.dataset("/strength/sigma_max", {3}, {12.0, 9.0, 7.0});
    f.dataset("/strength/sigma_dyn", {3}, {1.0, 1.0, 1.0});
    for (const char* c : {"pressure", "sigma_max", "sigma_dyn"})
      f.string_attribute(std::string("/strength/") + c, "unit", "GPa");
    f.string_attribute("/strength", "provenance_keys", "material");
    f.string_attribute("/strength", "material", "Si");
  }
  const auto t = read_strength_table(file);
  EXPECT_EQ(t.material, "Si");
  EXPECT_EQ(t.pressure, (std::vector<double>{0.0, 5e9, 10e9}));
  {
    h5fixture::File f(file);  // the same without units: which unit would it be? refused
    f.dataset("/strength/pressure", {3}, {0.0, 5.0, 10.0});
    f.dataset("/strength/sigma_max", {3}, {12.0, 9.0, 7.0});
    f.dataset("/strength/sigma_dyn", {3}, {1.0, 1.0, 1.0});
  }
  EXPECT_THROW(read_strength_table(file), InputError);
  std::filesystem::remove(file);
}
