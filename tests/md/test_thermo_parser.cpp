// The shear curve parser and the two strengths on synthetic LAMMPS output.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/md/thermo_parser.hpp"

using namespace wearscale;
using namespace wearscale::md;

namespace {
// A fix ave/time file: rise to 12 GPa at strain 0.30, drop, then stick-slip
// alternating 1.5 and 2.5 GPa: the mean over [0.4, 0.6] is exactly 2 GPa.
std::string synthetic(double end_strain = 0.6) {
  std::string s = "# Time-averaged data for fix curve\n# TimeStep v_strain v_tau v_p_n v_h c_t_mobile\n";
  for (int i = 1; i <= static_cast<int>(std::lround(end_strain * 100)); ++i) {
    const double strain = i / 100.0;
    const double tau = i <= 30 ? 0.4 * i : (i % 2 == 0 ? 1.5 : 2.5);
    s += fmt::format("{} {} {} {} {} {}\n", 2000 + 100 * i, strain, tau, 10.0 + 0.01 * (i % 3), 19.0, 300 + i);
  }
  return s;
}
}  // namespace

TEST(ThermoParser, PeakAndWindowMean) {
  const ShearCurve c = parse_shear_curve(synthetic(), "synthetic");
  ASSERT_EQ(c.samples.size(), 60u);
  EXPECT_DOUBLE_EQ(c.samples[0].strain, 0.01);
  EXPECT_DOUBLE_EQ(c.samples[0].shear_stress, 0.4e9);
  EXPECT_DOUBLE_EQ(c.samples[0].height, 19e-10);
  const ShearStrength s = shear_strength(c, 0.4, 0.6);
  EXPECT_NEAR(s.sigma_max, 12e9, 1e-3);
  EXPECT_NEAR(s.strain_at_max, 0.30, 1e-12);
  EXPECT_EQ(s.window_samples, 21u);  // strains 0.40 … 0.60
  // 21 rows: 11 at 1.5 (even) and 10 at 2.5 (odd).
  EXPECT_NEAR(s.sigma_dyn, (11 * 1.5 + 10 * 2.5) / 21 * 1e9, 1e-3);
  EXPECT_NEAR(s.sigma_dyn_std, std::sqrt(11.0 * 10.0) / 21 * 1e9, 1e-3);
  EXPECT_NEAR(s.normal_stress, 10.01e9, 0.02e9);
  EXPECT_NEAR(s.temperature_window, 350, 1e-9);
  EXPECT_DOUBLE_EQ(s.temperature_max, 360);
  EXPECT_TRUE(s.failed_before_window);
  const ShearStrength w = shear_strength(c, 0.41, 0.6);  // 20 rows, 10 of each: exactly 2 GPa
  EXPECT_NEAR(w.sigma_dyn, 2e9, 1e-3);
}

TEST(ThermoParser, PeakInsideWindowIsFlagged) {
  const ShearStrength s = shear_strength(parse_shear_curve(synthetic(), "s"), 0.2, 0.6);
  EXPECT_FALSE(s.failed_before_window);
}

TEST(ThermoParser, RunEndingBeforeWindowEndIsAnError) {
  const ShearCurve c = parse_shear_curve(synthetic(0.5), "short");
  EXPECT_THROW(shear_strength(c, 0.4, 0.6), NumericalError);
}

TEST(ThermoParser, GarbageIsDetected) {
  const std::string head = "# TimeStep v_strain v_tau v_p_n v_h c_t_mobile\n100 0.01 1 0 19 300\n";
  EXPECT_THROW(parse_shear_curve(head + "200 0.02 nan 0 19 300\n", "nan"), NumericalError);
  EXPECT_THROW(parse_shear_curve(head + "200 0.02 -inf 0 19 300\n", "inf"), NumericalError);
  EXPECT_THROW(parse_shear_curve(head + "200 0.02 1.0 0 19\n", "columns"), NumericalError);
  EXPECT_THROW(parse_shear_curve(head + "200 0.02 1.0x 0 19 300\n", "word"), NumericalError);
  EXPECT_THROW(parse_shear_curve(head + "100 0.02 1.0 0 19 300\n", "step"), NumericalError);
  EXPECT_THROW(parse_shear_curve(head + "200 0.02 1.0 0 0 300\n", "height"), NumericalError);
  EXPECT_THROW(parse_shear_curve("# only comments\n", "empty"), NumericalError);
  try {
    parse_shear_curve(head + "200 0.02 nan 0 19 300\n", "curve.dat");
    FAIL();
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("curve.dat:3"), std::string::npos) << e.what();
  }
}
