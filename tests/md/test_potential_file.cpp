// The Vashishta potential file rewritten with the thesis' 8 Å cutoff.
#include <gtest/gtest.h>

#include <sstream>

#include "wearscale/core/errors.hpp"
#include "wearscale/md/potential_file.hpp"

using namespace wearscale;
using namespace wearscale::md;

namespace {
// Two entries in LAMMPS' layout (from SiO.1990.vashishta): rc = 10, and an
// all-zero entry that must stay as it is.
const char* sample = R"(# Vashishta 1990
Si  Si  Si  0.82023  11  1.6  1.6  999  0.0  4.43
            0.0  10.0  0.0  0.0  0.0  0.0  0.0

O   Si  Si  163.859  9  -0.8  1.6  999  44.2357  4.43
            0.0  10.0  20.146  1.0  2.60  0.0  -0.77714596
Si  O   Si  0.0  0.0  0.0  0.0  0.0  0.0  0.0
            0.0  0.0  0.0  0.0  0.0  0.0  0.0
)";

std::vector<std::vector<std::string>> entries(const std::string& text) {
  std::stringstream ss(text);
  std::string line, all;
  while (std::getline(ss, line)) all += line.substr(0, line.find('#')) + " ";
  std::stringstream ws(all);
  std::vector<std::vector<std::string>> out;
  std::string w;
  while (ws >> w) {
    if (out.empty() || out.back().size() == 17) out.emplace_back();
    out.back().push_back(w);
  }
  return out;
}
}  // namespace

TEST(VashishtaCutoff, RewritesEveryNonZeroRcOnly) {
  const std::string out = vashishta_with_cutoff(sample, 8.0, "sample");
  const auto e = entries(out);
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0][11], "8");
  EXPECT_EQ(e[1][11], "8");
  EXPECT_EQ(e[1][14], "2.60") << "r0, the three-body cutoff, is kept";
  EXPECT_EQ(e[2][11], "0.0");
  EXPECT_NE(out.find("rc of every entry set to 8 Angstrom"), std::string::npos) << "the change is documented in the file";
}

TEST(VashishtaCutoff, InstalledFileIfPresent) {
  std::filesystem::path file;
  try {
    file = find_potential_file("SiO.1990.vashishta");
  } catch (const InputError&) {
    GTEST_SKIP() << "LAMMPS potentials not installed (apt-get install lammps)";
  }
  const auto e = entries(vashishta_with_cutoff(read_text_file(file), 8.0, file.string()));
  ASSERT_EQ(e.size(), 8u) << "all ordered Si/O triplets";
  for (const auto& entry : e) EXPECT_TRUE(entry[11] == "8" || entry[11] == "0.0") << entry[11];
}

TEST(VashishtaCutoff, GarbageIsRejected) {
  EXPECT_THROW(vashishta_with_cutoff("Si Si Si 1 2 3\n", 8.0, "x"), InputError);
  EXPECT_THROW(vashishta_with_cutoff(std::string(sample).replace(std::string(sample).find("4.43"), 4, "abc"), 8.0, "x"),
               InputError);
}
