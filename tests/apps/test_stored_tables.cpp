// The CSV tables committed to the repository follow the convention every
// table wearscale writes follows (docs/running.md, Outputs): one header line,
// the unit in each column's name, a .csv.json sidecar
// (tests/support/csv_table_check.hpp): the results stored under docs/figures/
// and the strength tables shipped in materials/data/ (pressure_Pa,
// sigma_max_Pa, sigma_dyn_Pa; their provenance in the sidecar's notes).
// Reads a few small files: milliseconds.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "csv_table_check.hpp"

namespace fs = std::filesystem;

TEST(StoredTables, FigureResultsAreTablesAsWearscaleWritesThem) {
  std::size_t tables = 0;
  const auto problems = csv_check::problems_under(fs::path(WEARSCALE_SOURCE_DIR) / "docs", tables);
  EXPECT_GE(tables, 1u) << "docs/figures/fig7_2_junction_sio2.csv at least";
  for (const auto& p : problems) ADD_FAILURE() << p;
}

TEST(StoredTables, ShippedStrengthTablesAreTablesAsWearscaleWritesThem) {
  std::size_t tables = 0;
  const auto dir = fs::path(WEARSCALE_SOURCE_DIR) / "materials" / "data";
  const auto problems = csv_check::problems_under(dir, tables);
  for (const auto& p : problems) ADD_FAILURE() << p;
  EXPECT_GE(tables, 4u) << "the thesis' and the LAMMPS smoke sets, Si and SiO2 at least";
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".csv") continue;
    std::ifstream in(e.path());
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "pressure_Pa,sigma_max_Pa,sigma_dyn_Pa") << e.path();
    std::ifstream sidecar(e.path().string() + ".json");
    std::stringstream ss;
    ss << sidecar.rdbuf();
    EXPECT_NE(ss.str().find("\"material: "), std::string::npos) << e.path() << ": its provenance names the material";
    EXPECT_NE(ss.str().find("\"source: "), std::string::npos) << e.path() << ": and where its numbers come from";
  }
}
