#include "wearscale/coupling/plots.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/program_path.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/coupling/palette.hpp"

extern "C" char** environ;

namespace wearscale::coupling {

namespace {
// gnuplot on the PATH, looked up once (empty: none).
const std::filesystem::path& gnuplot_program() {
  static const std::filesystem::path program = [] {
    auto found = find_on_path("gnuplot");
    if (found.empty()) log::info("gnuplot not found: no PNG plots (install it with: apt-get install gnuplot-nox)");
    return found;
  }();
  return program;
}

// gnuplot drawing `script`, its output and messages to /dev/null; the wait
// status, or -1 if it could not be started. Started directly (not through
// std::system, which ignores SIGINT in the caller while it waits): a Ctrl-C,
// which gnuplot answers by exiting with status 1, reaches this run as well.
int run_gnuplot(const std::filesystem::path& script) {
  posix_spawn_file_actions_t files;
  if (posix_spawn_file_actions_init(&files) != 0) return -1;
  posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  const std::string program = gnuplot_program().string(), script_name = script.string();
  char* argv[] = {const_cast<char*>(program.c_str()), const_cast<char*>(script_name.c_str()), nullptr};
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, program.c_str(), &files, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&files);
  if (spawned != 0) return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return status;
}

// A whole PNG: the signature, and the IEND chunk closing it (gnuplot exits 0
// even when the disk filled up under it, leaving a truncated image).
bool complete_png(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[8] = {}, tail[12] = {};
  if (!in.read(head, 8) || std::string_view(head, 8) != "\x89PNG\r\n\x1a\n") return false;
  in.seekg(-12, std::ios::end);
  return in.read(tail, 12) && std::string_view(tail + 4, 8) == "IEND\xae\x42\x60\x82";
}

// The data files of a plot are read where they are now: staged outputs of
// the run under their temporary names.
std::string data(const std::filesystem::path& csv) { return OutputSet::readable(csv).string(); }
}  // namespace

bool plotting_available() { return !gnuplot_program().empty(); }

std::optional<std::filesystem::path> render_plot(const std::string& script, const std::filesystem::path& png, int width,
                                                 int height) {
  if (!plotting_available()) return std::nullopt;
  const auto partial = partial_path(png);
  const auto script_file = partial_path(png.parent_path() / (png.stem().string() + ".gp"));
  try {
    write_temporary_file(script_file, fmt::format("set terminal pngcairo size {},{} font 'sans,11'\nset output '{}'\n{}",
                                                  width, height, partial.string(), script));
  } catch (const OutputError& e) {
    throw OutputError(fmt::format("{}; {} was not drawn", e.what(), png.string()));
  }
  const int status = run_gnuplot(script_file);
  std::error_code ec;
  std::filesystem::remove(script_file, ec);
  if (status != 0) {
    std::filesystem::remove(partial, ec);
    // Stopped by a signal (the job's, or this run's SIGINT/SIGTERM): the run
    // stops too, so that it is not taken as complete without its plot.
    if ((status != -1 && WIFSIGNALED(status)) || interrupt_requested())
      throw Interrupted(fmt::format("gnuplot was stopped by a signal while drawing {}", png.string()));
    log::warn("gnuplot could not draw {} ({})", png.string(),
              status == -1 ? "it could not be started" : fmt::format("exit status {}", WEXITSTATUS(status)));
    return std::nullopt;
  }
  if (!complete_png(partial)) {  // gnuplot said yes, but the file system did not take it all
    std::filesystem::remove(partial, ec);
    throw OutputError(fmt::format("cannot write {}: gnuplot left an incomplete image (is the disk full?); {} was not "
                                  "written",
                                  partial.string(), png.string()));
  }
  commit_file(partial, png);
  return png;
}

namespace {
// Okabe & Ito's colour-blind-safe palette (Color Universal Design, 2008), its
// yellow last (faint on white): the k-th series has the same colour in every
// figure of a sweep (friction curves, disc profiles).
namespace oi = okabe_ito;
constexpr const char* kColours[] = {oi::blue,   oi::vermillion, oi::bluish_green, oi::reddish_purple,
                                    oi::orange, oi::sky_blue,   oi::black,        oi::yellow};
// "RRGGBB", without the '#': the scripts prefix it, or an alpha ('#A0RRGGBB').
std::string colour(std::size_t k) { return kColours[k % (sizeof kColours / sizeof *kColours)] + 1; }

// A label in gnuplot's enhanced text, in single quotes: '_' printed as itself.
std::string literal(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '_' || c == '^' || c == '{' || c == '}' || c == '@' || c == '&' || c == '~') out += '\\';
    if (c == '\'') out += '\'';
    out += c;
  }
  return out;
}

// A title as a gnuplot string expression: each line literal() in single
// quotes, the lines joined by "\n" (a line break in gnuplot's double quotes).
std::string title_string(const std::string& title) {
  std::string out;
  for (std::size_t start = 0;;) {
    const auto end = title.find('\n', start);
    out += "'" + literal(title.substr(start, end == std::string::npos ? std::string::npos : end - start)) + "'";
    if (end == std::string::npos) return out;
    out += ".\"\\n\".";
    start = end + 1;
  }
}

// A long title broken into lines of at most `width` characters, at spaces
// (a long DEM caption ran off both edges of the plot, cut off).
std::string wrapped(const std::string& title, std::size_t width = 90) {
  std::string out, line, word;
  std::istringstream words(title);
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

// The sliding distances (second column) of a history table, in order.
std::vector<double> second_column(const std::filesystem::path& csv) {
  std::ifstream in(OutputSet::readable(csv));
  std::string line;
  std::vector<double> out;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    if (comma == std::string::npos) continue;
    try {
      out.push_back(std::stod(line.substr(comma + 1)));
    } catch (const std::exception&) {
      return out;
    }
  }
  return out;
}

}  // namespace

std::string sweep_title(const Config& c, const std::string& case_name, const std::string& key,
                        const std::string& series_key) {
  std::vector<std::string> parts;
  try {  // material names (a material defined in the case is a table: left out)
    if (c.has("materials.pin") && c.has("materials.disc"))
      parts.push_back(fmt::format("{} pin on {} disc", c.string("materials.pin"), c.string("materials.disc")));
  } catch (const std::exception&) {
  }
  struct Parameter {
    const char *key, *symbol, *unit;
    double scale;
    units::Dimension dim;
  };
  for (const auto& [name, symbol, unit, scale, dim] :
       {Parameter{"scale.macro.pin_radius", "R", "mm", units::mm, units::length},
        Parameter{"scale.macro.normal_load", "F_N", "N", units::N, units::force},
        Parameter{"scale.macro.velocity", "v", "mm/s", units::mm, units::velocity}}) {
    if (name == key || name == series_key || !c.has(name)) continue;  // swept: the legends give it
    try {
      parts.push_back(fmt::format("{} = {:.3g} {}", symbol, c.number(name, Range::any(), dim) / scale, unit));
    } catch (const std::exception&) {  // not a number (the run would have said so): left out of the title
    }
  }
  std::string swept = "swept: " + key;
  if (!series_key.empty()) swept += ", series: " + series_key;
  return fmt::format("{}\n{}{}{}", case_name, fmt::join(parts, ", "), parts.empty() ? "" : "; ", swept);
}

std::string legend_label(const std::string& run_label) {
  std::string out;
  std::istringstream words(run_label);
  for (std::string word; words >> word;) {
    const auto eq = word.find('=');
    std::string part = word;
    if (eq != std::string::npos) {
      const std::string key = word.substr(0, eq), value = word.substr(eq + 1);
      part = key + " = " + value;
      if (key == "thickness") {  // the oxide layer's, in metres
        if (value == "inf") {
          part = "h = ∞ (bulk oxide)";
        } else {
          char* end = nullptr;
          const double h = std::strtod(value.c_str(), &end);
          if (end == value.c_str() + value.size() && !value.empty())
            part = h == 0.0 ? std::string("h = 0 (no oxide)") : fmt::format("h = {:g} µm", h * 1e6);
        }
      }
    }
    out += (out.empty() ? "" : ", ") + part;
  }
  return out.empty() ? run_label : out;
}

namespace {
bool has_column(const std::filesystem::path& csv, const std::string& name) {
  std::ifstream in(OutputSet::readable(csv));  // a staged output is read under its temporary name
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') return ("," + line + ",").find("," + name + ",") != std::string::npos;
  return false;
}
}  // namespace

std::optional<std::filesystem::path> plot_friction_curves(const std::vector<FrictionCurve>& curves,
                                                          const std::filesystem::path& png, const std::string& title) {
  std::string mu, wear;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const auto& c = curves[k];
    const std::string rgb = colour(k);
    // One run: the title names it, the legend says what the lines are.
    const bool one = curves.size() == 1;
    const std::string name = literal(legend_label(c.label));
    if (has_column(c.csv, "friction_moving_average")) {
      mu += fmt::format("{}'{}' using ($1*1e3):(column('friction')) with lines lw 1 lc rgb '#A0{}' notitle, "
                        "'' using ($1*1e3):(column('friction_moving_average')) with lines lw 2 lc rgb '#{}' title '{}'",
                        k ? ", " : "", data(c.csv), rgb, rgb, one ? "moving average" : name);
    } else {
      mu += fmt::format("{}'{}' using ($1*1e3):(column('friction')) with lines lw 1.5 lc rgb '#{}' title '{}'", k ? ", " : "",
                        data(c.csv), rgb, one ? "μ" : name);
    }
    // One legend entry per series (its colour); the line style tells pin from disc.
    wear += fmt::format("{}'{}' using ($1*1e3):(column('pin_wear_m3')*1e18) with lines lw 1.5 dt 2 lc rgb '#{}' notitle, "
                        "'' using ($1*1e3):(column('disc_wear_m3')*1e18) with lines lw 1.5 lc rgb '#{}' {}",
                        k ? ", " : "", data(c.csv), rgb, rgb, one ? "notitle" : "title '" + name + "'");
  }
  if (curves.size() > 1)
    wear += ", NaN with lines lw 1.5 lc rgb 'black' title 'disc (solid)', "
            "NaN with lines lw 1.5 dt 2 lc rgb 'black' title 'pin (dashed)'";
  else if (curves.size() == 1)
    wear += fmt::format(", NaN with lines lw 1.5 lc rgb '#{0}' title 'disc', NaN with lines lw 1.5 dt 2 lc rgb '#{0}' "
                        "title 'pin'",
                        colour(0));
  // Both panels share the x axis and the same margins, so that their axes align
  // whatever the width of the tick labels and of the legend outside.
  const std::string script = fmt::format(
      "set datafile separator ','\nset datafile commentschars '#'\nset key autotitle columnhead\n"
      "set multiplot layout 2,1 title {}\n"
      "set lmargin at screen 0.10\nset rmargin at screen 0.74\n"
      "set ylabel 'friction coefficient μ'\nset yrange [0:1]\nset grid\nset key outside right top\n"
      "set xlabel 'sliding distance s [mm]'\n"
      "set label 1 'faint: raw μ; full: moving average' at graph 0.01, graph 0.93 font ',9'\n"
      "plot {}\nunset label 1\n"
      "set ylabel 'worn volume [µm³]'\nset autoscale y\nset yrange [0:*]\n"
      "plot {}\nunset multiplot\n",
      title_string(title), mu.empty() ? "NaN notitle" : mu, wear);
  return render_plot(script, png);
}

std::optional<std::filesystem::path> plot_disc_profiles(const std::vector<FrictionCurve>& profiles,
                                                        const std::filesystem::path& png, const std::string& title,
                                                        double layer_thickness) {
  std::string curves;
  for (std::size_t k = 0; k < profiles.size(); ++k)
    curves += fmt::format("{}'{}' using ($1*1e3):(-$2*1e6) with lines lw 2 lc rgb '#{}' title '{}'", k ? ", " : "",
                          data(profiles[k].csv), colour(k), literal(legend_label(profiles[k].label)));
  if (layer_thickness > 0.0 && std::isfinite(layer_thickness))
    curves += fmt::format(", {:.17g} with lines dt 2 lw 1.5 lc rgb 'black' title 'oxide/substrate interface'",
                          -layer_thickness * 1e6);
  return render_plot(fmt::format("set datafile separator ','\nset datafile commentschars '#'\nset key autotitle columnhead\n"
                                 "set title {}\nset xlabel 'across the track x [mm]'\nset ylabel 'disc surface [µm]'\n"
                                 "set grid\nset key outside right\nplot {}\n",
                                 title_string(title), curves),
                     png);
}

std::optional<std::filesystem::path> plot_friction_vs_thickness(const std::vector<SweepTable>& tables,
                                                                const std::filesystem::path& png) {
  // Column 1: thickness [m] (inf for bulk); the tables name their μ columns.
  std::string curves;
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const auto& t = tables[k];
    const std::string rgb = colour(k), file = data(t.csv);
    curves += fmt::format(
        "'{0}' using (finite($1)):(column('mu_final')) with linespoints pt 7 ps 1.3 lw 2 lc rgb '#{1}' "
        "title '{2}: final μ', \\\n"
        "'{0}' using (bulk($1)):(column('mu_final')) with points pt 5 ps 1.8 lc rgb '#{1}' title '{2}: bulk SiO_2', \\\n"
        "'{0}' using (finite($1)):(column('mu_mean')) with linespoints pt 6 dt 3 lw 1 lc rgb '#{1}' "
        "title '{2}: mean μ', \\\n",
        file, rgb, literal(legend_label(t.label)));
  }
  const std::string script = fmt::format(
      "set datafile separator ','\nset datafile commentschars '#'\nset key autotitle columnhead\n"
      "finite(x) = (x > 1) ? 1/0 : x*1e6   # oxide thicknesses [µm]\n"
      "bulk(x) = (x > 1) ? 6 : 1/0         # bulk (inf) placed at 6 µm, as in Fig. 9.25\n"
      "set xlabel 'oxide layer thickness h_{{layer}} [µm]'\nset ylabel 'friction coefficient μ'\n"
      "set xrange [-0.3:6.6]\nset yrange [0:1]\nset grid\nset key top left font ',9'\n"
      "set xtics ('0' 0, '1' 1, '2' 2, '3' 3, '4' 4, 'bulk' 6)\n"
      "set label 1 'bulk SiO_2 is drawn at 6 µm (the thesis places it there, Fig. 9.25)' at graph 0.35, graph 0.06 "
      "font ',9'\n"
      "plot {}     [0:3] 0.337 + 0.070*x with lines dt 2 lw 2 lc rgb 'black' title 'experiments: μ ≈ 0.337 + 0.070 h "
      "(9.1)'\n",
      curves);
  return render_plot(script, png);
}

std::optional<std::filesystem::path> plot_junction_force(const std::filesystem::path& history_csv,
                                                         const std::filesystem::path& png, const std::string& title) {
  // The samples are forces averaged over equal intervals of sliding; the last
  // one closes a shorter interval when the slide is not a whole number of
  // them, and its average of fewer steps draws a spike: it is left out.
  const auto s = second_column(history_csv);
  double last = s.empty() ? 0.0 : s.back();
  if (s.size() >= 3 && s[s.size() - 1] - s[s.size() - 2] < 0.99 * (s[s.size() - 2] - s[s.size() - 3]))
    last = s[s.size() - 2];
  return render_plot(fmt::format("set datafile separator ','\nset key autotitle columnhead top left\n"
                            "set title {} font ',11'\nset xlabel 'sliding distance [nm]'\nset ylabel 'force [nN]'\n"
                            "last = {:.17g}\nset grid\n"
                            "plot '{}' every ::1 using ($2 <= last ? $2*1e9 : 1/0):($3*1e9) with lines lw 2 "
                            "lc rgb '#0072B2' title 'tangential F_T', "
                            "'' every ::1 using ($2 <= last ? $2*1e9 : 1/0):($4*1e9) with lines lw 1.5 "
                            "lc rgb '#D55E00' title 'normal F_N'\n",
                            title_string(wrapped(title)), last, data(history_csv)),
                png);
}

std::optional<std::filesystem::path> plot_junction_strength(const std::filesystem::path& runs_csv,
                                                            const std::filesystem::path& png, const std::string& title,
                                                            const std::vector<double>& contact_ratios, double sigma,
                                                            double p_crit, double length) {
  // Columns: 1 D/L, 2 p_N [Pa], 6 peak p_T [Pa], 9 outcome (0 flattened, 1 sheared, 2 detached). Each D/L in
  // its colour, each outcome its marker; (7.9), p_T = (D/L) σ, is each D/L's plateau, (7.10),
  // p_T = (p_N/p_crit) σ, the same line for all: drawn once, in black, over the plateaus' ends.
  std::string plots;
  const double s = sigma / 1e9, pc = p_crit / 1e9;
  const std::string file = data(runs_csv);
  struct Outcome {
    int code, point;
    const char* name;
  };
  constexpr Outcome outcomes[] = {{1, 7, "sheared"}, {0, 6, "flattened"}, {2, 9, "detached (rolling)"}};
  for (std::size_t k = 0; k < contact_ratios.size(); ++k) {
    const double c = contact_ratios[k];
    const std::string rgb = colour(k);
    const std::string label = length > 0.0 ? fmt::format("D = {:.3g} nm (D/L = {:.3g})", c * length * 1e9, c)
                                           : fmt::format("D/L = {:.3g}", c);
    for (const auto& o : outcomes)
      plots += fmt::format("'{}' every ::1 using (($1=={:.17g} && $9=={}) ? $2/1e9 : 1/0):($6/1e9) with points pt {} "
                           "ps 1.6 lw 1.5 lc rgb '#{}' notitle, ",
                           file, c, o.code, o.point, rgb);
    plots += fmt::format("(x < {0:.17g}*{1:.17g} ? {0:.17g}*{2:.17g} : 1/0) with lines lw 2 lc rgb '#{3}' title '{4}', ",
                         c, pc, s, rgb, literal(label));
  }
  // (7.10) from the smallest plateau's end on: below it the model is the plateaus.
  const double from = contact_ratios.empty() ? 0.0 : *std::min_element(contact_ratios.begin(), contact_ratios.end()) * pc;
  plots += fmt::format("(x >= {0:.17g} ? x/{1:.17g}*{2:.17g} : 1/0) with lines lw 2 lc rgb 'black' "
                       "title '(7.10): p_T = (p_N/p_{{crit}}) σ', ",
                       from, pc, s);
  plots += "x with lines dt 2 lc rgb 'black' title 'p_T = p_N', ";
  plots += "NaN with lines lw 2 lc rgb '#999999' title '(7.9): p_T = (D/L) σ, a line per D', ";
  for (std::size_t k = 0; k < std::size(outcomes); ++k)
    plots += fmt::format("{}NaN with points pt {} ps 1.6 lw 1.5 lc rgb 'black' title 'DEM run: {}'", k ? ", " : "",
                         outcomes[k].point, outcomes[k].name);
  return render_plot(
      fmt::format("set datafile separator ','\nset key outside right top\n"
                  "set offsets 0, graph 0.05, graph 0.05, 0\nset title {}\nset xlabel 'normal pressure p_N [GPa]'\n"
                  "set ylabel 'peak tangential stress p_T [GPa]'\nset grid\nset xrange [0:*]\nset yrange [0:*]\n"
                  "set samples 1000\nset label 1 'fit: σ = {:.3g} GPa, p_{{crit}} = {:.3g} GPa' at graph 0.5, graph 0.05\n"
                  "plot {}\n",
                  title_string(title), s, pc, plots),
      png, 1100, 700);
}

}  // namespace wearscale::coupling
