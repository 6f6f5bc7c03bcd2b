#include "wearscale/md/thermo_parser.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::md {

namespace {
constexpr double gpa = 1e9, angstrom = 1e-10;
}

ShearCurve parse_shear_curve(std::string_view text, const std::string& source) {
  ShearCurve c;
  c.source = source;
  std::stringstream in{std::string(text)};
  std::string line;
  long line_no = 0;
  auto bad = [&](long step, const std::string& what) {
    return NumericalError("LAMMPS shear test", step, "shear curve", fmt::format("{}:{}: {}", source, line_no, what));
  };
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::stringstream row(line);
    std::vector<std::string> cells;
    std::string cell;
    while (row >> cell) cells.push_back(cell);
    if (cells.size() != 6) throw bad(-1, fmt::format("{} columns, expected 6 (step strain tau pN h T)", cells.size()));
    double v[6];
    for (int i = 0; i < 6; ++i) {
      char* end = nullptr;
      errno = 0;
      v[i] = std::strtod(cells[i].c_str(), &end);
      if (end == cells[i].c_str() || *end != '\0') throw bad(-1, fmt::format("column {} is '{}', not a number", i + 1, cells[i]));
      if (!std::isfinite(v[i])) throw bad(std::lround(v[0]), fmt::format("column {} is {} (the run diverged)", i + 1, cells[i]));
    }
    ShearSample s{std::lround(v[0]), v[1], v[2] * gpa, v[3] * gpa, v[4] * angstrom, v[5]};
    if (!c.samples.empty() && s.step <= c.samples.back().step)
      throw bad(s.step, fmt::format("step {} after step {}: not increasing (two runs in one file?)", s.step,
                                    c.samples.back().step));
    if (s.height <= 0.0) throw bad(s.step, fmt::format("sheared height {} Å is not positive", v[4]));
    c.samples.push_back(s);
  }
  if (c.samples.empty()) throw NumericalError("LAMMPS shear test", 0, "shear curve", fmt::format("{}: no data row", source));
  return c;
}

ShearCurve read_shear_curve(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw NumericalError("LAMMPS shear test", 0, "shear curve",
                         fmt::format("{}: missing (LAMMPS ended before shearing?)", file.string()));
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_shear_curve(ss.str(), file.string());
}

double initial_slope(const ShearCurve& c, double max_strain) {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (const auto& s : c.samples) {
    if (!(s.strain > 0.0 && s.strain <= max_strain)) continue;
    n += 1.0;
    sx += s.strain;
    sy += s.shear_stress;
    sxx += s.strain * s.strain;
    sxy += s.strain * s.shear_stress;
  }
  const double det = n * sxx - sx * sx;
  if (n < 3.0 || !(det > 0.0))
    throw NumericalError("LAMMPS shear test", c.samples.empty() ? 0 : c.samples.front().step, "elastic slope",
                         fmt::format("{}: {} rows with strain in (0, {:g}]; at least 3 are needed (sample more often: "
                                     "md.sample_steps)",
                                     c.source, n, max_strain));
  return (n * sxy - sx * sy) / det;
}

ShearStrength shear_strength(const ShearCurve& c, double window_begin, double window_end) {
  ShearStrength r;
  r.window_begin = window_begin;
  r.window_end = window_end;
  if (c.samples.empty()) throw NumericalError("LAMMPS shear test", 0, "shear curve", c.source + ": empty");
  const auto peak = std::max_element(c.samples.begin(), c.samples.end(),
                                     [](const ShearSample& a, const ShearSample& b) { return a.shear_stress < b.shear_stress; });
  r.sigma_max = peak->shear_stress;
  r.strain_at_max = peak->strain;
  // The last row averages the last `sample_steps` steps before the run
  // stopped at the final strain: its mean strain lies up to one row's
  // increment below it.
  const double last = c.samples.back().strain;
  const double increment = c.samples.size() > 1 ? (last - c.samples.front().strain) / static_cast<double>(c.samples.size() - 1) : 0.0;
  if (last + increment < window_end)
    throw NumericalError("LAMMPS shear test", c.samples.back().step, "strain",
                         fmt::format("{}: the run ends at strain {:.4g}, before the end {:g} of the dynamic-strength "
                                     "window",
                                     c.source, last, window_end));
  double sum = 0.0, sum2 = 0.0, pn = 0.0, temp = 0.0;
  for (const auto& s : c.samples) {
    r.temperature_max = std::max(r.temperature_max, s.temperature);
    if (s.strain < window_begin || s.strain > window_end) continue;
    ++r.window_samples;
    sum += s.shear_stress;
    sum2 += s.shear_stress * s.shear_stress;
    pn += s.normal_stress;
    temp += s.temperature;
  }
  if (r.window_samples == 0)
    throw NumericalError("LAMMPS shear test", c.samples.back().step, "strain window",
                         fmt::format("{}: no row with strain in [{:g}, {:g}]", c.source, window_begin, window_end));
  const double n = static_cast<double>(r.window_samples);
  r.sigma_dyn = sum / n;
  r.sigma_dyn_std = std::sqrt(std::max(0.0, sum2 / n - r.sigma_dyn * r.sigma_dyn));
  r.normal_stress = pn / n;
  r.temperature_window = temp / n;
  r.failed_before_window = r.strain_at_max < window_begin;
  return r;
}

}  // namespace wearscale::md
