#include "wearscale/coupling/plots.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/output_set.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/coupling/palette.hpp"

namespace wearscale::coupling {

namespace fs = std::filesystem;

namespace {

// Okabe & Ito's colour-blind-safe palette (Color Universal Design, 2008), its
// yellow last (faint on white): the k-th series has the same colour in every
// figure of a sweep (friction curves, disc profiles). A gnuplot word list.
std::string colour_words() {
  namespace oi = okabe_ito;
  return fmt::format("{}", fmt::join({oi::blue, oi::vermillion, oi::bluish_green, oi::reddish_purple, oi::orange,
                                      oi::sky_blue, oi::black, oi::yellow},
                                     " "));
}

// What every kind's script shares after the prologue: the colours, and a
// loop drawing the figure as PNG, then as PDF (7 in wide, for a paper).
std::string kind_script(std::string_view body, int png_width, int png_height) {
  const double pdf_height = 7.0 * png_height / png_width;
  return fmt::format(
      "colours = \"{}\"\n"
      "colour(c) = word(colours, (c - 1) % words(colours) + 1)\n"
      "faint(c) = \"#A0\".colour(c)[2:]\n"
      "do for [FORMAT in \"png pdf\"] {{\n"
      "if (FORMAT eq \"png\") {{ set terminal pngcairo size {},{} font \"sans,11\" }} "
      "else {{ set terminal pdfcairo size 7in,{:.2f}in font \"sans,9\" }}\n"
      "set output name.\".\".FORMAT\n"
      "{}"
      "unset output\n"
      "}}\n",
      colour_words(), png_width, png_height, pdf_height, body);
}

// The columns `names` of a wearscale CSV table (one header line), read where
// the file is now (a staged output under its temporary name).
std::map<std::string, std::vector<double>> read_columns(const fs::path& csv, const std::vector<std::string>& names) {
  std::ifstream in(OutputSet::readable(csv));
  std::string line;
  std::map<std::string, std::vector<double>> out;
  if (!std::getline(in, line)) return out;
  std::vector<int> index(names.size(), -1);
  {
    std::istringstream header(line);
    std::string cell;
    for (int c = 0; std::getline(header, cell, ','); ++c)
      for (std::size_t k = 0; k < names.size(); ++k)
        if (cell == names[k]) index[k] = c;
  }
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    for (std::size_t k = 0; k < names.size(); ++k)
      if (index[k] >= 0 && static_cast<std::size_t>(index[k]) < cells.size()) {
        char* end = nullptr;
        const double v = std::strtod(cells[static_cast<std::size_t>(index[k])].c_str(), &end);
        out[names[k]].push_back(v);
      }
  }
  return out;
}

// `file` named relative to `folder`, which holds it.
fs::path inside(const fs::path& file, const fs::path& folder) {
  const fs::path relative = fs::absolute(file).lexically_normal().lexically_relative(fs::absolute(folder).lexically_normal());
  if (relative.empty() || *relative.begin() == "..")
    throw std::logic_error(fmt::format("{} is not inside {}", file.string(), folder.string()));
  return relative;
}

// "4.41×10⁻⁵" for small or large numbers, "0.0441" otherwise: 3 significant digits.
std::string readable_number(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "–" : x > 0 ? "∞" : "−∞";
  if (x == 0.0 || (std::fabs(x) >= 1e-3 && std::fabs(x) < 1e5)) return fmt::format("{:.3g}", x);
  const int e = static_cast<int>(std::floor(std::log10(std::fabs(x))));
  double m = x / std::pow(10.0, e);
  std::string mantissa = fmt::format("{:.3g}", m);
  static const char* superscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string exponent = e < 0 ? "⁻" : "";
  for (char c : std::to_string(std::abs(e))) exponent += superscript[c - '0'];
  return mantissa + "×10" + exponent;
}

// A long title broken into lines of at most `width` characters, at spaces
// (a long DEM caption ran off both edges of the plot, cut off).
std::string wrapped(const std::string& title, std::size_t width = 90) {
  std::string out;
  std::istringstream lines(title);
  for (std::string text; std::getline(lines, text);) {
    if (!out.empty()) out += "\n";
    if (text.size() <= width) {  // as it is, its spaces too
      out += text;
      continue;
    }
    std::string line, word;
    std::istringstream words(text);
    std::string wrapped_line;
    while (words >> word) {
      while (word.size() > width) {  // a word longer than a line (a name of thousands of characters): cut, at a character
        std::size_t cut = width;
        while (cut > 0 && (static_cast<unsigned char>(word[cut]) & 0xC0) == 0x80) --cut;
        if (cut == 0) cut = width;
        if (!line.empty()) wrapped_line += line + "\n";
        wrapped_line += word.substr(0, cut) + "\n";
        line.clear();
        word.erase(0, cut);
      }
      if (!line.empty() && line.size() + 1 + word.size() > width) {
        wrapped_line += line + "\n";
        line.clear();
      }
      line += (line.empty() ? "" : " ") + word;
    }
    out += wrapped_line + line;
  }
  return out;
}

// A title for a figure: its lines wrapped, at most 6, each character checked.
std::string title_text(const std::string& title) { return figure_text(wrapped(figure_text(title, 600, true)), 600, true); }

// A legend entry: one line, at most 60 characters.
std::string entry_text(const std::string& label) { return figure_text(label, 60); }

// --- the kinds' scripts (constant text) -------------------------------------

// μ(s) and V(s): texts 1 title, 2 volume unit, 3 its scale from m³, 4 rows
// between the pin's markers, 5 the number of runs n; then per run c: its
// table, its legend entry, the disc's entry and the pin's (one run).
constexpr std::string_view kFriction = R"gp(title = given_text(1)
volume_unit = given_text(2)
volume_scale = given_number(3)
marker_every = int(given_number(4))
n = int(given_number(5))
file(c) = given_text(5 + 4*c - 3)
label(c) = given_text(5 + 4*c - 2)
disc_entry(c) = given_text(5 + 4*c - 1)
pin_entry(c) = given_text(5 + 4*c)
set multiplot layout 2,1 title title noenhanced
set lmargin 11
set rmargin 3
set grid
set key noenhanced
unset xlabel
set ylabel "friction coefficient μ"
set yrange [0:1.3]
set ytics 0, 0.2, 1
set key top left horizontal maxrows 2 samplen 2.5 Left reverse
plot for [c=1:n] file(c) using (column("distance_m")*1e3):(column("friction")) with lines lw 1 lc rgb faint(c) notitle, \
     for [c=1:n] file(c) using (column("distance_m")*1e3):(column("friction_moving_average")) with lines lw 2 lc rgb colour(c) title (n == 1 ? "moving average" : label(c)), \
     NaN with lines lw 1 lc rgb (n == 1 ? faint(1) : "#A0000000") title (n == 1 ? "raw μ" : "raw μ (faint)")
set xlabel "sliding distance s [mm]"
set ylabel "worn volume [".volume_unit."]"
set autoscale y
set yrange [0:*]
set ytics autofreq
set format y "%g"
set key top left vertical maxrows auto samplen 4 Left reverse
plot for [c=1:n] file(c) using (column("distance_m")*1e3):(column("disc_wear_m3")*volume_scale) with lines lw 2 lc rgb colour(c) title (n == 1 ? disc_entry(c) : ""), \
     for [c=1:n] file(c) using (column("distance_m")*1e3):(column("pin_wear_m3")*volume_scale) with linespoints lw 1.5 dt 2 pt 6 ps 0.9 pi marker_every lc rgb colour(c) title (n == 1 ? pin_entry(c) : ""), \
     NaN with lines lw 2 lc rgb "black" title (n == 1 ? "" : "disc"), \
     NaN with linespoints lw 1.5 dt 2 pt 6 ps 0.9 lc rgb "black" title (n == 1 ? "" : "pin (dashed)")
unset multiplot
)gp";

// The disc across the track: texts 1 title, 2 the interface's depth [µm]
// (nan: none drawn), 3 its legend entry, 4 the number of runs n; then per
// run its table and its legend entry.
constexpr std::string_view kDiscProfiles = R"gp(title = given_text(1)
interface = given_number(2)
interface_entry = given_text(3)
n = int(given_number(4))
file(c) = given_text(4 + 2*c - 1)
label(c) = given_text(4 + 2*c)
set title title noenhanced
set xlabel "across the track x [mm] (0: the pin's axis)"
set ylabel "disc surface [µm]"
set grid
set key bottom left noenhanced Left reverse
set offsets 0, 0, graph 0.08, graph 0.05
plot for [c=1:n] file(c) using (column("x_m")*1e3):(-column("worn_depth_m")*1e6) with lines lw 2 lc rgb colour(c) title label(c), \
     (interface == interface ? -interface : NaN) with lines dt 2 lw 1.5 lc rgb "black" title (interface == interface ? interface_entry : "")
)gp";

// Fig. 9.25 and the specific wear rates: texts 1 title, 2 the number of
// tables n; then per table its file and its name ("" for one table).
constexpr std::string_view kFrictionVsThickness = R"gp(title = given_text(1)
n = int(given_number(2))
file(c) = given_text(2 + 2*c - 1)
label(c) = given_text(2 + 2*c)
entry(c, what) = (label(c) eq "" ? what : label(c).": ".what)
finite(h) = (h > 1) ? NaN : h*1e6      # thicknesses in µm; bulk (inf) apart
bulk(h) = (h > 1) ? 6 : NaN            # bulk drawn at 6 µm, as in Fig. 9.25
set multiplot layout 2,1 title title noenhanced
set lmargin 11
set rmargin 3
set grid
set key noenhanced
set xrange [-0.3:6.6]
set xtics ("0" 0, "1" 1, "2" 2, "3" 3, "4" 4, "bulk" 6)
unset xlabel
set ylabel "friction coefficient μ"
set yrange [0:1.3]
set ytics 0, 0.2, 1
set key top left horizontal maxrows 2 samplen 2.5 Left reverse
set offsets 0, 0, 0, 0
set label 1 "bulk oxide drawn at 6 µm (Fig. 9.25)" at graph 0.98, graph 0.06 right font ",9"
plot for [c=1:n] file(c) using (finite(column(1))):(column("mu_final")) with linespoints pt 7 ps 1.3 lw 2 lc rgb colour(c) title entry(c, "final μ"), \
     for [c=1:n] file(c) using (bulk(column(1))):(column("mu_final")) with points pt 5 ps 1.8 lc rgb colour(c) notitle, \
     for [c=1:n] file(c) using (finite(column(1))):(column("mu_mean")) with linespoints pt 6 dt 3 lw 1 lc rgb colour(c) title entry(c, "mean μ"), \
     [0:3] 0.337 + 0.070*x with lines dt 2 lw 2 lc rgb "black" title "experiments: μ ≈ 0.337 + 0.070 h (9.1)"
unset label 1
set xlabel "oxide layer thickness h [µm]"
set ylabel "specific wear rate k [mm³/(N·m)]"
set autoscale y
set yrange [0:*]
set ytics autofreq
set format y "%g"
set key top left vertical maxrows auto samplen 3 Left reverse
set offsets 0, 0, graph 0.3, 0
plot for [c=1:n] file(c) using (finite(column(1))):(column("disc_specific_wear_rate_mm3_per_N_per_m")) with linespoints pt 7 ps 1.3 lw 2 lc rgb colour(c) title entry(c, "disc"), \
     for [c=1:n] file(c) using (bulk(column(1))):(column("disc_specific_wear_rate_mm3_per_N_per_m")) with points pt 5 ps 1.8 lc rgb colour(c) notitle, \
     for [c=1:n] file(c) using (finite(column(1))):(column("pin_specific_wear_rate_mm3_per_N_per_m")) with linespoints pt 6 ps 1.3 dt 2 lw 1.5 lc rgb colour(c) title entry(c, "pin"), \
     for [c=1:n] file(c) using (bulk(column(1))):(column("pin_specific_wear_rate_mm3_per_N_per_m")) with points pt 4 ps 1.8 lw 1.5 lc rgb colour(c) notitle
unset multiplot
)gp";

// A DEM junction's forces: texts 1 title, 2 the history table, 3 the last
// sliding distance drawn [m].
constexpr std::string_view kJunctionForce = R"gp(title = given_text(1)
file = given_text(2)
last = given_number(3)
set title title noenhanced font ",11"
set xlabel "sliding distance [nm]"
set ylabel "force [nN]"
set key top left Left reverse
set grid
plot file using (column(2) <= last ? column(2)*1e9 : NaN):(column(3)*1e9) with lines lw 2 lc rgb colour(1) title "tangential F_T", \
     file using (column(2) <= last ? column(2)*1e9 : NaN):(column(4)*1e9) with lines lw 1.5 lc rgb colour(2) title "normal F_N"
)gp";

// Peak p_T against p_N with the model (7.9)-(7.10): texts 1 title, 2 the runs'
// table (columns 1 D/L, 2 p_N [Pa], 6 peak p_T [Pa], 9 outcome: 0 flattened,
// 1 sheared, 2 detached), 3 σ [GPa], 4 p_crit [GPa], 5 where (7.10) starts
// [GPa], 6 the fit's line, 7 the number of D/L values n; then per D/L its
// value and its legend entry.
constexpr std::string_view kJunctionStrength = R"gp(title = given_text(1)
file = given_text(2)
sigma = given_number(3)
p_crit = given_number(4)
from = given_number(5)
fit = given_text(6)
n = int(given_number(7))
ratio(c) = given_number(7 + 2*c - 1)
label(c) = given_text(7 + 2*c)
same(a, b) = abs(a - b) <= 1e-9*abs(b)
outcome_code(o) = word("1 0 2", o) + 0
outcome_point(o) = word("7 6 9", o) + 0
outcome_name(o) = word("sheared flattened detached", o)
set key top left Left reverse
set offsets 0, graph 0.05, graph 0.6, 0    # room above the points for the legend
set title title noenhanced
set xlabel "normal pressure p_N [GPa]"
set ylabel "peak tangential stress p_T [GPa]"
set grid
set xrange [0:*]
set yrange [0:*]
set samples 1000
set label 1 fit at graph 0.98, graph 0.05 right noenhanced
plot for [c=1:n] for [o=1:3] file using ((same(column(1), ratio(c)) && column(9) == outcome_code(o)) ? column(2)/1e9 : NaN):(column(6)/1e9) with points pt outcome_point(o) ps 1.6 lw 1.5 lc rgb colour(c) notitle, \
     for [c=1:n] (x < ratio(c)*p_crit ? ratio(c)*sigma : NaN) with lines lw 2 lc rgb colour(c) title label(c) noenhanced, \
     (x >= from ? x/p_crit*sigma : NaN) with lines lw 2 lc rgb "black" title "(7.10): p_T = (p_N/p_{crit}) σ", \
     x with lines dt 2 lc rgb "black" title "p_T = p_N", \
     NaN with lines lw 2 lc rgb "#999999" title "(7.9): p_T = (D/L) σ, a line per D", \
     for [o=1:3] NaN with points pt outcome_point(o) ps 1.6 lw 1.5 lc rgb "black" title "DEM run: ".outcome_name(o)
unset label 1
)gp";

const std::string& script(std::string_view body, int width, int height) {
  static std::map<const char*, std::string> built;  // one per kind, made once
  static std::mutex guard;
  std::lock_guard lock(guard);
  auto& s = built[body.data()];
  if (s.empty()) s = kind_script(body, width, height);
  return s;
}

}  // namespace

std::string length_words(double m) {
  if (m == 0.0) return "0";
  if (std::isinf(m)) return m > 0 ? "∞" : "−∞";
  if (std::isnan(m)) return "nan";
  const double a = std::fabs(m);
  if (a < 1e-7) return fmt::format("{:.3g} nm", m / units::nm);
  if (a < 1e-3) return fmt::format("{:.3g} µm", m / units::um);
  if (a < 1.0) return fmt::format("{:.3g} mm", m / units::mm);
  return fmt::format("{:.3g} m", m);
}

namespace {
// The value of a key as a number in SI, its bare numbers SI in `dim` (as the
// case reads them); nullopt if it is not one.
std::optional<double> si_value(const std::string& value, units::Dimension dim) {
  try {
    const auto q = units::parse_quantity(value);
    if (q.dimension == dim || q.dimension == units::dimensionless) return q.value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::string text_or(const Config& c, const std::string& key, const std::string& fallback) {
  try {
    if (c.has(key)) return c.string(key);
  } catch (const std::exception&) {  // a table (a material defined in the case): its name is the key's
  }
  return fallback;
}

// The pin-on-disc keys in words, with the unit a reader gives them; `title`:
// stated in a run's title (the others only when swept).
struct Named {
  const char *key, *words, *unit;
  double scale;
  units::Dimension dim;
  bool title;
};
constexpr Named kNamed[] = {
    {"scale.macro.pin_radius", "pin radius", "mm", units::mm, units::length, true},
    {"scale.macro.normal_load", "load", "N", units::N, units::force, true},
    {"scale.macro.velocity", "speed", "mm/s", units::mm, units::velocity, true},
    {"scale.macro.nonplanarity.slope", "disc tilt", "", 1.0, units::dimensionless, true},
    {"scale.macro.distance", "sliding distance", "m", 1.0, units::length, false},
    {"scale.macro.time_step", "time step", "s", 1.0, units::time, false},
    {"scale.macro.nonplanarity.period", "tilt period", "mm", units::mm, units::length, false},
};
}  // namespace

std::string parameter_words(const Config& c, const std::string& key, const std::string& value) {
  if (key == "materials.layer.thickness") {
    const std::string disc = text_or(c, "materials.disc", "disc");
    const std::string layer = text_or(c, "materials.layer.material", disc);
    if (const auto h = si_value(value, units::length)) {
      if (*h == 0.0) return fmt::format("no {} layer", layer);
      if (std::isinf(*h)) return fmt::format("bulk {}", layer);
      return fmt::format("{} layer {}", layer, length_words(*h));
    }
  }
  for (const auto& n : kNamed)
    if (key == n.key)
      if (const auto v = si_value(value, n.dim))
        return fmt::format("{} {:.3g}{}{}", n.words, *v / n.scale, *n.unit ? " " : "", n.unit);
  std::string leaf = key.substr(key.rfind('.') + 1);
  std::replace(leaf.begin(), leaf.end(), '_', ' ');
  return leaf + " " + value;
}

std::string pin_on_disc_parameters(const Config& c, const std::vector<std::string>& left_out) {
  auto out_of = [&](const std::string& key) { return std::find(left_out.begin(), left_out.end(), key) != left_out.end(); };
  std::vector<std::string> parts;
  if (c.has("materials.pin") && c.has("materials.disc"))
    parts.push_back(fmt::format("{} pin on {} disc", text_or(c, "materials.pin", "pin"), text_or(c, "materials.disc", "disc")));
  const std::string thickness = "materials.layer.thickness";
  if (c.has(thickness) && !out_of(thickness)) try {
      const double h = c.number(thickness, Range::non_negative().or_infinite(), units::length);
      parts.push_back(parameter_words(c, thickness, fmt::format("{}", h)));
    } catch (const std::exception&) {  // not a number (the run would have said so): left out
    }
  for (const auto& n : kNamed) {
    if (!n.title || out_of(n.key) || !c.has(n.key)) continue;
    try {
      const double v = c.number(n.key, Range::any(), n.dim);
      if (n.dim == units::dimensionless && v == 0.0) continue;  // no tilt
      parts.push_back(fmt::format("{} {:.3g}{}{}", n.words, v / n.scale, *n.unit ? " " : "", n.unit));
    } catch (const std::exception&) {  // not a number (the run would have said so): left out
    }
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

namespace {
// A case's name as a title's first line(s): at most 150 characters, so that the
// parameters after it fit in what a figure draws of a text (kMaxTextBytes).
std::string name_line(const std::string& case_name) { return figure_text(case_name, 150, true); }
}  // namespace

std::string run_title(const Config& c, const std::string& case_name) {
  const std::string parameters = pin_on_disc_parameters(c);
  return parameters.empty() ? name_line(case_name) : name_line(case_name) + "\n" + parameters;
}

std::string sweep_title(const Config& c, const std::string& case_name, const std::string& key,
                        const std::string& series_key) {
  auto swept = [&](const std::string& k) {
    if (k == "materials.layer.thickness") return text_or(c, "materials.layer.material", text_or(c, "materials.disc", "layer")) + " layer thickness";
    for (const auto& n : kNamed)
      if (k == n.key) return std::string(n.words);
    std::string leaf = k.substr(k.rfind('.') + 1);
    std::replace(leaf.begin(), leaf.end(), '_', ' ');
    return leaf;
  };
  const std::string parameters = pin_on_disc_parameters(c, {key, series_key});
  std::string what = "swept: " + swept(key);
  if (!series_key.empty()) what += "; series: " + swept(series_key);
  return fmt::format("{}\n{}{}{}", name_line(case_name), parameters, parameters.empty() ? "" : "; ", what);
}

Figure friction_figure(const std::string& name, const std::string& title, const std::vector<FrictionCurve>& curves,
                       const fs::path& folder) {
  Figure f{name, script(kFriction, 1000, 760), {}, {}};
  // Worn volumes in mm³ (what tribologists read), in µm³ when under 10⁻³ mm³.
  double largest = 0.0;
  std::size_t rows = 0;
  std::vector<std::map<std::string, std::vector<double>>> tables;
  const std::string k_pin = "pin_specific_wear_rate_mm3_per_N_per_m", k_disc = "disc_specific_wear_rate_mm3_per_N_per_m";
  for (const auto& c : curves) {
    tables.push_back(read_columns(c.csv, {"pin_wear_m3", "disc_wear_m3", k_pin, k_disc}));
    for (const char* v : {"pin_wear_m3", "disc_wear_m3"})
      for (const double x : tables.back()[v])
        if (std::isfinite(x)) largest = std::max(largest, x);
    rows = std::max(rows, tables.back()["pin_wear_m3"].size());
  }
  const bool mm3 = largest == 0.0 || largest >= 1e-12;
  f.add("title", title_text(title));
  f.add("volume unit", mm3 ? "mm³" : "µm³");
  f.add("volume scale from m³", mm3 ? 1e9 : 1e18);
  f.add("rows between the pin's markers", static_cast<double>(std::max<std::size_t>(1, rows / 12)));
  f.add("runs", static_cast<double>(curves.size()));
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const auto file = inside(curves[k].csv, folder);
    f.data.push_back(file);
    f.add("table", file.string());
    f.add("legend", entry_text(curves[k].label));
    auto last = [&](const std::string& column) {
      const auto& v = tables[k][column];
      return v.empty() ? std::nan("") : v.back();
    };
    f.add("disc", fmt::format("disc, k = {} mm³/(N·m)", readable_number(last(k_disc))));
    f.add("pin", fmt::format("pin (dashed), k = {} mm³/(N·m)", readable_number(last(k_pin))));
  }
  return f;
}

Figure disc_profiles_figure(const std::string& name, const std::string& title,
                            const std::vector<FrictionCurve>& profiles, double layer_thickness, const fs::path& folder) {
  Figure f{name, script(kDiscProfiles, 1000, 700), {}, {}};
  f.add("title", title_text(title));
  const bool interface = layer_thickness > 0.0 && std::isfinite(layer_thickness);
  f.add("interface depth [µm]", interface ? layer_thickness * 1e6 : std::nan(""));
  f.add("interface", "oxide/substrate interface");
  f.add("runs", static_cast<double>(profiles.size()));
  for (const auto& p : profiles) {
    const auto file = inside(p.csv, folder);
    f.data.push_back(file);
    f.add("table", file.string());
    f.add("legend", entry_text(p.label));
  }
  return f;
}

Figure friction_vs_thickness_figure(const std::string& name, const std::string& title,
                                    const std::vector<SweepTable>& tables, const fs::path& folder) {
  Figure f{name, script(kFrictionVsThickness, 1000, 860), {}, {}};
  f.add("title", title_text(title));
  f.add("tables", static_cast<double>(tables.size()));
  for (const auto& t : tables) {
    const auto file = inside(t.csv, folder);
    f.data.push_back(file);
    f.add("table", file.string());
    f.add("legend", tables.size() == 1 ? std::string() : entry_text(t.label));
  }
  return f;
}

Figure junction_force_figure(const std::string& name, const std::string& title, const fs::path& history_csv,
                             const fs::path& folder) {
  // The samples are forces averaged over equal intervals of sliding; the last
  // one closes a shorter interval when the slide is not a whole number of
  // them, and its average of fewer steps draws a spike: it is left out.
  std::vector<double> s;
  {
    std::ifstream in(OutputSet::readable(history_csv));
    std::string line;
    std::getline(in, line);  // the header
    while (std::getline(in, line)) {
      const auto comma = line.find(',');
      if (comma == std::string::npos) continue;
      char* end = nullptr;
      s.push_back(std::strtod(line.c_str() + comma + 1, &end));
    }
  }
  double last = s.empty() ? 0.0 : s.back();
  if (s.size() >= 3 && s[s.size() - 1] - s[s.size() - 2] < 0.99 * (s[s.size() - 2] - s[s.size() - 3]))
    last = s[s.size() - 2];
  Figure f{name, script(kJunctionForce, 1000, 700), {}, {}};
  const auto file = inside(history_csv, folder);
  f.add("title", title_text(title));
  f.add("history", file.string());
  f.add("last distance drawn [m]", last);
  f.data.push_back(file);
  return f;
}

Figure junction_strength_figure(const std::string& name, const std::string& title, const fs::path& runs_csv,
                                const std::vector<double>& contact_ratios, double sigma, double p_crit, double length,
                                const fs::path& folder) {
  Figure f{name, script(kJunctionStrength, 1100, 760), {}, {}};
  const double s = sigma / 1e9, pc = p_crit / 1e9;
  // (7.10) from the smallest plateau's end on: below it the model is the plateaus.
  const double from = contact_ratios.empty() ? 0.0 : *std::min_element(contact_ratios.begin(), contact_ratios.end()) * pc;
  const auto file = inside(runs_csv, folder);
  f.add("title", title_text(title));
  f.add("runs", file.string());
  f.add("sigma [GPa]", s);
  f.add("p_crit [GPa]", pc);
  f.add("(7.10) from p_N [GPa]", from);
  f.add("fit", fmt::format("fit: σ = {:.3g} GPa, p_crit = {:.3g} GPa", s, pc));
  f.add("D/L values", static_cast<double>(contact_ratios.size()));
  for (const double c : contact_ratios) {
    f.add("D/L", c);
    f.add("legend", length > 0.0 ? fmt::format("D = {:.3g} nm (D/L = {:.3g})", c * length * 1e9, c)
                                 : fmt::format("D/L = {:.3g}", c));
  }
  f.data.push_back(file);
  return f;
}

}  // namespace wearscale::coupling
