// The CSV tables committed to the repository, in the two formats docs/running.md
// (Outputs) names: results stored under docs/figures/ as wearscale writes
// them (one header line, the unit in each column's name, a .csv.json
// sidecar: tests/support/csv_table_check.hpp), and the shipped strength tables
// of materials/data/ as input tables (provenance in leading '#' lines, then one
// header line pressure_GPa,sigma_max_GPa,sigma_dyn_GPa and numbers:
// pandas.read_csv(path, comment='#')). Reads a few small files: milliseconds.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "csv_table_check.hpp"

namespace fs = std::filesystem;

TEST(StoredTables, FigureResultsAreTablesAsWearscaleWritesThem) {
  std::size_t tables = 0;
  const auto problems = csv_check::problems_under(fs::path(WEARSCALE_SOURCE_DIR) / "docs", tables);
  EXPECT_GE(tables, 1u) << "docs/figures/fig7_2_junction_sio2.csv at least";
  for (const auto& p : problems) ADD_FAILURE() << p;
}

TEST(StoredTables, ShippedStrengthTablesAreCommentsThenOneHeaderAndNumbers) {
  std::size_t tables = 0;
  for (const auto& e : fs::directory_iterator(fs::path(WEARSCALE_SOURCE_DIR) / "materials" / "data")) {
    if (e.path().extension() != ".csv") continue;
    ++tables;
    std::ifstream in(e.path());
    std::string line;
    int comments = 0, rows = 0;
    while (std::getline(in, line) && line.starts_with("#")) ++comments;
    EXPECT_GE(comments, 1) << e.path() << ": the provenance lines";
    EXPECT_EQ(line, "pressure_GPa,sigma_max_GPa,sigma_dyn_GPa") << e.path();
    while (std::getline(in, line)) {
      ++rows;
      EXPECT_EQ(line.find('#'), std::string::npos) << e.path() << ": '#' after the header: " << line;
      const auto cells = csv_check::split_row(line);
      ASSERT_EQ(cells.size(), 3u) << e.path() << ": " << line;
      for (const auto& c : cells) EXPECT_TRUE(csv_check::is_number(c)) << e.path() << ": " << line;
    }
    EXPECT_GE(rows, 2) << e.path();
  }
  EXPECT_EQ(tables, 4u) << "the thesis' and the LAMMPS smoke sets, Si and SiO2";
}
