// A pin-on-disc run's outputs as a user meets them: pandas reads every
// number as a float, h5py reads text as str and scalars of shape (), the
// disc's x is one axis in run.h5, final_surfaces.xdmf and disc_profile.csv,
// the specific wear rate k = V/(F s) is given in mm³/(N·m), the swept key's
// column carries its unit, and every figure comes as PNG and PDF with the
// script that draws it again. No folder or case name, however hostile, runs
// a command or costs a figure.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_outputs_cli_");
const fs::path work = work_scratch.path();
const std::string source = WEARSCALE_SOURCE_DIR;
const std::string pin_on_disc = "run '" + source + "/cases/pin_on_disc_si_oxide.toml'";
const std::string small = " --set scale.macro.grid=32 --set scale.macro.distance=0.001";
const std::string python = WEARSCALE_TEST_PYTHON;  // Debian's, with python3-pandas and python3-h5py
const std::string probe = python + " '" + source + "/tests/apps/outputs_probe.py'";

bool gnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }
bool pandas_and_h5py() { return std::system((python + " -c 'import pandas, h5py' >/dev/null 2>&1").c_str()) == 0; }

// `text` as a shell word, whatever it holds.
std::string shell_word(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Every file named `name` under `dir`.
std::vector<fs::path> find(const fs::path& dir, const std::string& name) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.path().filename() == name) out.push_back(e.path());
  return out;
}

// The texts of a figure's _labels.tsv, decoded ("what\tx<hex>" a line).
std::vector<std::string> figure_texts(const fs::path& tsv) {
  std::ifstream in(tsv);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) {
    const auto x = line.find("\tx");
    std::string text;
    for (std::size_t k = x + 2; k + 1 < line.size(); k += 2) text += static_cast<char>(std::stoi(line.substr(k, 2), nullptr, 16));
    out.push_back(text);
  }
  return out;
}

void expect_figure(const fs::path& dir, const std::string& name) {
  for (const std::string ext : {".gp", "_labels.tsv"}) EXPECT_TRUE(fs::exists(dir / (name + ext))) << dir / (name + ext);
  if (!gnuplot()) return;
  for (const std::string ext : {".png", ".pdf"}) EXPECT_TRUE(fs::exists(dir / (name + ext))) << dir / (name + ext);
}
}  // namespace

// The reproduction: a folder name closing gnuplot's quote and calling system().
TEST(OutputsCli, AnOutputFolderNamedLikeGnuplotCodeRunsNothingAndGetsEveryFigure) {
  const fs::path dir = work / "hostile";
  const std::string name = "x'; system('touch PWNED'); print('";
  const auto r = run_cli(pin_on_disc + small + " --out " + shell_word(name) + " -q", dir);  // as in the report
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(find(dir, "PWNED"), ::testing::IsEmpty());
  EXPECT_FALSE(fs::exists("PWNED"));
  EXPECT_EQ(r.err.find("gnuplot"), std::string::npos) << r.err;
  expect_figure(dir / name, "friction");
}

struct HostileName {
  std::string id, text;
};
void PrintTo(const HostileName& h, std::ostream* os) { *os << h.id; }
class OutputsCliHostileName : public ::testing::TestWithParam<HostileName> {};

// The same text as the folder and as the case's name (its figure's title):
// the run succeeds, nothing is run, the figure is drawn and titled by it.
TEST_P(OutputsCliHostileName, AsAFolderAndAsTheCaseNameItIsDrawnAndNeverRun) {
  const auto& h = GetParam();
  const fs::path dir = work / ("name-" + h.id);
  std::string toml_string;  // the name as a TOML basic string
  for (const char c : h.text) toml_string += c == '"' ? "\\\"" : c == '\\' ? "\\\\" : c == '\n' ? "\\n" : std::string(1, c);
  const auto r = run_cli(pin_on_disc + small + " --out=" + shell_word(h.text) + " --set " +
                             shell_word("case.name=\"" + toml_string + "\"") + " -q",
                         dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(find(dir, "PWNED"), ::testing::IsEmpty());
  EXPECT_EQ(r.err.find("gnuplot"), std::string::npos) << r.err;
  expect_figure(dir / h.text, "friction");
  const auto texts = figure_texts(dir / h.text / "friction_labels.tsv");
  ASSERT_FALSE(texts.empty());
  EXPECT_EQ(texts.front().substr(0, texts.front().find("\nSiO2 pin")), h.text) << "the title's first line";
}

INSTANTIATE_TEST_SUITE_P(
    Names, OutputsCliHostileName,
    ::testing::Values(HostileName{"double_quote", "\"; system(\"touch PWNED\"); print(\""},
                      HostileName{"newline", "two\nlines"}, HostileName{"backslash", "back\\slash \\n"},
                      HostileName{"command_substitution", "$(touch PWNED)"}, HostileName{"backticks", "`touch PWNED`"},
                      HostileName{"at_macro", "@ARG0 @name"}, HostileName{"unicode", "µm³ ∞ 日本"},
                      HostileName{"spaces", "a  b c"}, HostileName{"enhanced_text", "h_{layer}^2 &{x} ~y #z"},
                      HostileName{"option", "-e system('touch PWNED')"}),
    [](const ::testing::TestParamInfo<HostileName>& i) { return i.param.id; });

// `gnuplot friction.gp` in the run's folder draws the figure again, as a user edits and redraws it.
TEST(OutputsCli, TheKeptScriptDrawsTheFigureAgainInItsFolder) {
  if (!gnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = work / "redraw";
  const auto r = run_cli(pin_on_disc + small + " --out run -q", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  fs::remove(dir / "run" / "friction.png");
  fs::remove(dir / "run" / "friction.pdf");
  const pid_t child = ::fork();
  if (child == 0) {
    if (::chdir((dir / "run").c_str()) != 0) ::_exit(2);
    ::execlp("gnuplot", "gnuplot", "friction.gp", static_cast<char*>(nullptr));
    ::_exit(3);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_GT(fs::file_size(dir / "run" / "friction.png"), 10000u);
  EXPECT_GT(fs::file_size(dir / "run" / "friction.pdf"), 5000u);
}

// A case of more than HDF5's 64 KiB of attribute header (its name alone):
// the run completes, run.h5 keeps the whole case, and the figure is drawn
// with the name cut in its title.
TEST(OutputsCli, ACaseLargerThanAnAttributeHeaderIsKeptWholeInRunH5) {
  const fs::path dir = work / "long-name";
  fs::create_directories(dir);
  std::string toml = slurp(source + "/cases/pin_on_disc_si_oxide.toml");
  const auto at = toml.find("name = \"");
  ASSERT_NE(at, std::string::npos);
  const std::string name(70000, 'x');
  toml.replace(at, toml.find('\n', at) - at, "name = \"" + name + "\"");
  std::ofstream(dir / "long.toml") << toml;
  const auto r = run_cli("run long.toml" + small + " --out run -q", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  if (gnuplot()) {  // its title cut to what gnuplot reads of a text
    EXPECT_TRUE(fs::exists(dir / "run" / "friction.png")) << r.err;
    EXPECT_TRUE(fs::exists(dir / "run" / "friction.pdf")) << r.err;
  }
  if (!pandas_and_h5py()) GTEST_SKIP() << "h5py is not installed (Debian: python3-h5py)";
  EXPECT_EQ(std::system((python + " -c \"import h5py, sys; f = h5py.File(sys.argv[1], 'r'); "
                         "assert ('x' * 70000) in f.attrs['case_toml']\" '" +
                         (dir / "run" / "run.h5").string() + "'")
                            .c_str()),
            0);
}

// pandas and h5py on one run with an oxide (layered) and one on bare Si.
TEST(OutputsCli, PandasAndH5pyReadARunAsDocumented) {
  if (!pandas_and_h5py()) GTEST_SKIP() << "pandas or h5py is not installed (Debian: python3-pandas, python3-h5py)";
  const fs::path dir = work / "probe";
  for (const auto& [h, layered] : std::vector<std::pair<std::string, std::string>>{{"1e-7", "1"}, {"0", "0"}}) {
    const auto r = run_cli(pin_on_disc + " --set scale.macro.grid=32 --set scale.macro.distance=0.005 --set "
                                         "materials.layer.thickness=" + h + " --out h" + h + " -q",
                           dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(std::system((probe + " run '" + (dir / ("h" + h)).string() + "' 1 " + layered).c_str()), 0) << "h = " << h;
  }
}

// The oxide sweep: its table's first column is the thickness in metres
// (layer_thickness_m, unit "m"), every figure of the sweep is drawn, and the
// runs' tables agree with it (grooves nan without an oxide on a substrate).
TEST(OutputsCli, TheSweepTableNamesTheThicknessInMetresAndEveryFigureIsDrawn) {
  const fs::path dir = work / "sweep";
  fs::create_directories(dir);
  std::ofstream(dir / "sweep.toml") << slurp(source + "/cases/oxide_thickness_sweep.toml");
  const auto r = run_cli("run sweep.toml" + small + " --set 'sweep.values=[0, 1e-6, \"inf\"]' --out s -q", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string table = slurp(dir / "s" / "friction_vs_thickness.csv");
  EXPECT_EQ(table.substr(0, table.find(',')), "layer_thickness_m");
  const auto sidecar = nlohmann::json::parse(slurp(dir / "s" / "friction_vs_thickness.csv.json"));
  EXPECT_EQ(sidecar["units"]["layer_thickness_m"], "m");
  for (const char* figure : {"friction_curves", "disc_profiles", "friction_vs_thickness"}) expect_figure(dir / "s", figure);
  for (const char* run : {"thickness=0", "thickness=1e-06", "thickness=inf"}) expect_figure(dir / "s" / run, "friction");
  // The runs' figures tell them apart by their oxide in their titles.
  EXPECT_THAT(figure_texts(dir / "s" / "thickness=1e-06" / "friction_labels.tsv").front(), HasSubstr("SiO2 layer 1 µm"));
  EXPECT_THAT(figure_texts(dir / "s" / "thickness=0" / "friction_labels.tsv").front(), HasSubstr("no SiO2 layer"));
  EXPECT_THAT(figure_texts(dir / "s" / "thickness=inf" / "friction_labels.tsv").front(), HasSubstr("bulk SiO2"));
  if (!pandas_and_h5py()) GTEST_SKIP() << "pandas or h5py is not installed";
  EXPECT_EQ(std::system((probe + " sweep '" + (dir / "s").string() + "'").c_str()), 0);
  EXPECT_EQ(std::system((probe + " run '" + (dir / "s" / "thickness=0").string() + "' 1 0").c_str()), 0);
  EXPECT_EQ(std::system((probe + " run '" + (dir / "s" / "thickness=inf").string() + "' 1 0").c_str()), 0);
}
