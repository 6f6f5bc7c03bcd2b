// Every kind of field output opens right in ParaView: the XY plane, x along
// X as in wearscale's own x/y and PNGs, the grid's exact spacing, and at the
// point (x_i, y_j) the value wearscale stored for it; field snapshots of a
// pin-on-disc run as a time series over the sliding distance.
//
// The structural check (tests/support/xdmf_check.hpp: the sidecar against
// its HDF5 file) always runs. The same outputs are then opened with
// ParaView's own readers through pvpython when it is installed
// (apt-get install paraview); without it that part is skipped, saying so.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "xdmf_check.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

static const ScratchDir work_scratch("wearscale_paraview_cli_");

const std::filesystem::path work = work_scratch.path();

bool have_pvpython() {
  static const bool found = std::system("command -v pvpython >/dev/null 2>&1") == 0;
  return found;
}

#define SKIP_WITHOUT_PARAVIEW()                                                                              \
  if (!have_pvpython())                                                                                      \
  GTEST_SKIP() << "pvpython not found (Debian: apt-get install paraview): the ParaView check is skipped, " \
                  "the structural check above ran"

// What ParaView's readers show of `xmf`: per reader, dims, origin, spacing,
// bounds, time steps and `array` at the point nearest to (x, y).
std::map<std::string, nlohmann::json> paraview_probe(const fs::path& xmf, const std::string& array, double x, double y,
                                                     std::optional<double> time = std::nullopt) {
  const auto log = work / "pvpython.log";
  const std::string cmd =
      fmt::format("pvpython '{}/tests/apps/paraview_probe.py' '{}' '{}' {:.17g} {:.17g} {} > '{}' 2>&1",
                  WEARSCALE_SOURCE_DIR, fs::absolute(xmf).string(), array, x, y,
                  time ? fmt::format("{:.17g}", *time) : "", log.string());
  const int status = std::system(cmd.c_str());
  const std::string out = slurp(log);
  const auto at = out.rfind("PROBE ");
  if (status != 0 || at == std::string::npos) {
    ADD_FAILURE() << "pvpython failed on " << xmf << ":\n" << out;
    return {};
  }
  const auto j = nlohmann::json::parse(out.substr(at + 6, out.find('\n', at) - at - 6));
  return j.get<std::map<std::string, nlohmann::json>>();
}

// ParaView sees `nx` × `ny` points in the plane z = 0 from (x0, y0), `dx`,
// `dy` apart, and `value` at (x0 + i dx, y0 + j dy); Warp By Scalar spans
// `range` (the field's min, max) along z.
void expect_paraview_shows(const fs::path& xmf, const std::string& array, std::size_t nx, std::size_t ny,
                           std::array<double, 4> geometry, std::size_t i, std::size_t j, double value,
                           std::optional<double> time = std::nullopt,
                           std::optional<std::pair<double, double>> range = std::nullopt) {
  const auto [x0, y0, dx, dy] = geometry;
  const double x = x0 + static_cast<double>(i) * dx, y = y0 + static_cast<double>(j) * dy;
  const auto readers = paraview_probe(xmf, array, x, y, time);
  ASSERT_EQ(readers.size(), 2u) << "XDMFReader and Xdmf3ReaderS";
  for (const auto& [name, v] : readers) {
    SCOPED_TRACE(name + " on " + xmf.filename().string());
    EXPECT_EQ(v["dims"], (nlohmann::json{nx, ny, 1})) << "x fastest, one plane";
    EXPECT_EQ(v["origin"], (nlohmann::json{x0, y0, 0.0}));
    EXPECT_EQ(v["spacing"][0].get<double>(), dx) << "double-precision spacing";
    EXPECT_EQ(v["spacing"][1].get<double>(), dy);
    EXPECT_EQ(v["bounds"][4].get<double>(), 0.0) << "the XY plane";
    EXPECT_EQ(v["bounds"][5].get<double>(), 0.0);
    EXPECT_NEAR(v["point"][0].get<double>(), x, 1e-12 * std::abs(dx) * static_cast<double>(nx));
    EXPECT_NEAR(v["point"][1].get<double>(), y, 1e-12 * std::abs(dy) * static_cast<double>(ny));
    EXPECT_EQ(v["value"].get<double>(), value) << array << " at (" << x << ", " << y << ")";
    if (range) {  // Warp By Scalar lifts the plane along z by the field, x and y unchanged
      // (its output points are float32: compared to float precision)
      auto near = [](const nlohmann::json& a, double b) { EXPECT_NEAR(a.get<double>(), b, 1e-6 * std::abs(b)); };
      for (int k : {0, 1, 2, 3}) near(v["warp_bounds"][k], v["bounds"][k].get<double>());
      near(v["warp_bounds"][4], range->first);
      near(v["warp_bounds"][5], range->second);
    }
  }
}

double stored(const fs::path& h5, const std::string& dataset, std::size_t i, std::size_t j) {
  const wearscale::H5Reader r(h5);
  const auto shape = r.shape(dataset);
  return r.read_series(dataset).at(i * shape.at(1) + j);  // wearscale's order: x slowest
}

// A 32 × 16 rough surface over 100 µm × 50 µm (nx ≠ ny catches swapped axes).
const std::string surface = "surface generate --nx 32 --ny 16 --size 1e-4,5e-5 --hurst 0.8 --kl 1 --ks 8 --h-rms 1e-6 "
                            "--seed 7 --out surface --file rough.h5";
constexpr double dx = 1e-4 / 32, dy = 5e-5 / 16;

}  // namespace

TEST(ParaViewCli, AGeneratedSurfaceOpensInTheXYPlaneWithXAlongX) {
  ASSERT_EQ(run_cli(surface, work).status, 0);
  const fs::path xmf = work / "surface" / "rough.xdmf", h5 = work / "surface" / "rough.h5";
  expect_xdmf_describes(xmf, h5, {32, 16}, {"/surface/height"}, std::array<double, 4>{0.0, 0.0, dx, dy});
  SKIP_WITHOUT_PARAVIEW();
  const auto h = wearscale::H5Reader(h5).read_series("/surface/height");
  expect_paraview_shows(xmf, "height", 32, 16, {0.0, 0.0, dx, dy}, 21, 5, stored(h5, "/surface/height", 21, 5),
                        std::nullopt, std::pair{*std::min_element(h.begin(), h.end()), *std::max_element(h.begin(), h.end())});
}

TEST(ParaViewCli, ContactFieldsOpenInTheXYPlaneWithXAlongX) {
  ASSERT_EQ(run_cli(surface, work).status, 0);
  const auto r = run_cli("contact --surface surface/rough.h5 --e-star 1e11 --pressure 2e7 --out contact", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path xmf = work / "contact" / "contact.xdmf", h5 = work / "contact" / "contact.h5";
  expect_xdmf_describes(xmf, h5, {32, 16},
                        {"/surface/height", "/fields/pressure", "/fields/gap", "/fields/displacement", "/fields/contact"},
                        std::array<double, 4>{0.0, 0.0, dx, dy});
  SKIP_WITHOUT_PARAVIEW();
  // The highest pressure, where a point of contact certainly is.
  const wearscale::H5Reader reader(h5);
  const auto p = reader.read_series("/fields/pressure");
  const auto k = static_cast<std::size_t>(std::max_element(p.begin(), p.end()) - p.begin());
  expect_paraview_shows(xmf, "pressure", 32, 16, {0.0, 0.0, dx, dy}, k / 16, k % 16, p[k]);
}

TEST(ParaViewCli, WearMapsOpenWithTheirFirstAxisAlongX) {
  const auto r = run_cli("wearmap analytic2d --n 12 --out map2d", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path xmf = work / "map2d" / "wearmap_analytic2d.xdmf", h5 = work / "map2d" / "wearmap_analytic2d.h5";
  expect_xdmf_describes(xmf, h5, {12, 12},
                        {"/region", "/ratio/R_sep", "/ratio/R_comb", "/ratio/kappa", "/ratio/kappa_min"});
  const auto rough = run_cli("wearmap rough --n 16 --ql 2 --seeds 1 --n-loads 3 --n-dstar 2 --out rough", work);
  ASSERT_EQ(rough.status, 0) << rough.err;
  const fs::path rxmf = work / "rough" / "wearmap_rough.xdmf", rh5 = work / "rough" / "wearmap_rough.h5";
  expect_xdmf_describes(rxmf, rh5, {3, 2},
                        {"/maps/count_mean", "/maps/count_sd", "/maps/volume_mean", "/maps/volume_sd", "/maps/valid"},
                        std::array<double, 4>{0.0, 0.0, 1.0, 1.0});
  SKIP_WITHOUT_PARAVIEW();
  // d_r/d* (x) over [0, 3] and d_a/d* (y) over [0, 6], sampled at cell centres: the first node half a cell in.
  const wearscale::H5Reader reader(h5);
  const auto xs = reader.read_series("/axes/dr_over_dstar"), ys = reader.read_series("/axes/da_over_dstar");
  const double mdx = xs[1] - xs[0], mdy = ys[1] - ys[0];
  const auto ratio = reader.read_series("/ratio/R_sep");
  const std::array<double, 4> geometry{xs[0], ys[0], mdx, mdy};
  const auto readers = paraview_probe(xmf, "R_sep", xs[9], ys[2]);
  for (const auto& [name, v] : readers) {
    SCOPED_TRACE(name);
    EXPECT_EQ(v["dims"], (nlohmann::json{12, 12, 1}));
    EXPECT_NEAR(v["origin"][0].get<double>(), geometry[0], 1e-12);
    EXPECT_NEAR(v["origin"][1].get<double>(), geometry[1], 1e-12);
    EXPECT_EQ(v["value"].get<double>(), ratio[9 * 12 + 2]) << "R_sep at (d_r, d_a) = (" << xs[9] << ", " << ys[2] << ")";
  }
  expect_paraview_shows(rxmf, "count_mean", 3, 2, {0.0, 0.0, 1.0, 1.0}, 2, 1, stored(rh5, "/maps/count_mean", 2, 1));
}

// A 32² pin-on-disc run with field snapshots (and the keys `sets`) into
// `out`: the time steps of its fields.xdmf, each checked against run.h5.
std::vector<std::pair<double, std::vector<std::string>>> snapshot_run(const std::string& sets, const std::string& out) {
  const std::string pin_on_disc = "'" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/pin_on_disc_si_oxide.toml'";
  const auto r = run_cli("run " + pin_on_disc + " --set scale.macro.grid=32 --set scale.macro.integrator=explicit" + sets +
                             " --out " + out,
                         work);
  EXPECT_EQ(r.status, 0) << r.err;
  if (r.status != 0) return {};
  return expect_xdmf_time_series(work / out / "fields.xdmf", work / out / "run.h5", {32, 32});
}

TEST(ParaViewCli, PinOnDiscSnapshotsCloserThanATenthOfAMillimetreKeepTheirOwnFields) {
  // 16 µm steps, a snapshot at each: groups once named by the distance to
  // 0.1 mm shared one group among six steps, whose fields the last overwrote.
  const auto steps = snapshot_run(
      " --set scale.macro.distance=0.0004 --set scale.macro.time_step=0.002 --set scale.macro.fields_every=1", "close");
  const wearscale::H5Reader reader(work / "close" / "run.h5");
  EXPECT_EQ(steps.size(), 26u) << "one snapshot per sample: 25 steps of 16 um and the final state";
  std::set<std::string> groups;
  for (const auto& [time, datasets] : steps) {
    const std::string group = datasets[0].substr(0, datasets[0].rfind('/'));
    EXPECT_TRUE(groups.insert(group).second) << group << " holds two snapshots";
    EXPECT_EQ(reader.number_attribute(group, "distance"), time) << group;
  }
}

TEST(ParaViewCli, PinOnDiscSnapshotsAreATimeSeriesOverTheSlidingDistance) {
  const auto steps = snapshot_run(" --set scale.macro.distance=0.004 --set scale.macro.fields_every=8", "pod");
  const fs::path h5 = work / "pod" / "run.h5";
  const wearscale::H5Reader reader(h5);
  ASSERT_GE(steps.size(), 2u);
  double previous = -1.0;
  for (const auto& [time, datasets] : steps) {
    ASSERT_EQ(datasets.size(), 3u);
    const std::string group = datasets[0].substr(0, datasets[0].rfind('/'));
    EXPECT_THAT(datasets, ::testing::ElementsAre(group + "/pin", group + "/disc", group + "/pressure"));
    EXPECT_EQ(reader.number_attribute(group, "distance"), time) << "the step's time is its group's distance";
    EXPECT_EQ(reader.string_attribute(group, "distance_unit"), "m");
    EXPECT_GT(time, previous) << "steps in order of sliding distance";
    previous = time;
  }
  EXPECT_LE(previous, 0.004 * (1 + 1e-9));
  const fs::path final_xmf = work / "pod" / "final_surfaces.xdmf";
  const double l = 2e-3 / 32;  // the pin's axis at x = y = 0: the window from -1 mm (docs/fields.md)
  expect_xdmf_describes(final_xmf, h5, {32, 32}, {"/macro/final/pin", "/macro/final/disc", "/macro/final/pressure"},
                        std::array<double, 4>{-1e-3, -1e-3, l, l});
  EXPECT_GE(reader.number_attribute("/macro/final", "distance"), previous) << "the final state after the last snapshot";
  SKIP_WITHOUT_PARAVIEW();
  const auto& [time, datasets] = steps.back();
  const std::string pin = datasets[0];
  const auto readers = paraview_probe(work / "pod" / "fields.xdmf", "pin", 20 * l - 1e-3, 11 * l - 1e-3, time);
  for (const auto& [name, v] : readers) {
    SCOPED_TRACE(name);
    ASSERT_EQ(v["times"].size(), steps.size());
    for (std::size_t k = 0; k < steps.size(); ++k) EXPECT_EQ(v["times"][k].get<double>(), steps[k].first);
    EXPECT_EQ(v["dims"], (nlohmann::json{32, 32, 1}));
    EXPECT_EQ(v["value"].get<double>(), stored(h5, pin, 20, 11)) << "pin height at the last snapshot";
  }
  expect_paraview_shows(final_xmf, "pressure", 32, 32, {-1e-3, -1e-3, l, l}, 16, 13,
                        stored(h5, "/macro/final/pressure", 16, 13));
}
