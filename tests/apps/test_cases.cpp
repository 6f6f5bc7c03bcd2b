// Case regression: every file in cases/ runs (reduced by the overrides its
// gold file lists) and reproduces the checked-in headline figures within the
// tolerances stated in tests/cases/<case>.gold.json. Changing a gold file is
// a reviewed commit.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace fs = std::filesystem;

namespace {
std::vector<fs::path> case_files() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(WEARSCALE_SOURCE_DIR) / "cases"))
    if (e.path().extension() == ".toml") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

class CaseRegression : public ::testing::TestWithParam<fs::path> {};

TEST_P(CaseRegression, ReproducesItsGoldFigures) {
  const auto& file = GetParam();
  const auto gold_path = fs::path(WEARSCALE_SOURCE_DIR) / "tests" / "cases" / (file.stem().string() + ".gold.json");
  ASSERT_TRUE(fs::exists(gold_path)) << "every case needs a gold file: " << gold_path;
  const auto gold = nlohmann::json::parse(slurp(gold_path));
  // The command that runs the case: `run` for scale pipelines, `contact` for contact studies.
  std::string args = gold.value("command", std::string("run")) + " '" + file.string() + "' --json --out out";
  for (const auto& o : gold.value("overrides", nlohmann::json::array())) args += " --set '" + o.get<std::string>() + "'";
  const auto work = fs::temp_directory_path() / ("wearscale_case_" + file.stem().string() + "_" + std::to_string(::getpid()));
  const auto r = run_cli(args, work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  auto compare = [&](const nlohmann::json& results, const nlohmann::json& expected_results, const std::string& where) {
    for (const auto& [name, expected] : expected_results.items()) {
      ASSERT_TRUE(results.contains(name)) << where << ": " << name;
      const double got = results[name]["value"].get<double>();
      const double want = expected["value"].get<double>();
      const double tol = expected.value("rtol", 0.0) * std::abs(want) + expected.value("atol", 0.0);
      EXPECT_NEAR(got, want, tol) << where << ": " << name;
    }
  };
  if (gold.contains("runs")) {  // a sweep: figures per swept value ("VALUE SERIES" with a [sweep.series])
    ASSERT_TRUE(out.contains("sweep")) << "the case should be a sweep";
    for (const auto& [value, expected] : gold["runs"].items()) {
      bool found = false;
      for (const auto& run : out["sweep"]["runs"])
        if ((run.contains("series") ? run["value"].get<std::string>() + " " + run["series"].get<std::string>()
                                    : run["value"].get<std::string>()) == value) {
          compare(run["results"], expected, file.filename().string() + " at " + value);
          found = true;
        }
      EXPECT_TRUE(found) << "no run for swept value " << value;
    }
  } else {
    compare(out["results"], gold["results"], file.filename().string());
  }
  fs::remove_all(work);
}

INSTANTIATE_TEST_SUITE_P(Cases, CaseRegression, ::testing::ValuesIn(case_files()),
                         [](const auto& p) {
                           std::string n = p.param.stem().string();
                           for (auto& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });
