#include "wearscale/coupling/figure.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/program_path.hpp"

extern "C" char** environ;

namespace wearscale::coupling {

namespace fs = std::filesystem;

namespace {

// What every figure's script starts with: the figure's name from the
// script's own (ARG0, "friction.gp" → "friction"), its texts read from
// <name>_labels.tsv as strings (hexadecimal → bytes, a byte at a time through
// sprintf("%c"): no text is ever parsed as a command), and the CSV settings
// of wearscale's tables (one header line, names read by column("...")).
// `reset session` keeps the `set datafile` settings: the texts are read
// without a header line even when the script before it in the same gnuplot
// (a gnuplot draws a folder's figures several in turn) set columnheaders, as
// every one does.
constexpr std::string_view kPrologue = R"(# Draws NAME.png and NAME.pdf, NAME being this file's name without .gp:
#   gnuplot NAME.gp      (in this folder)
# The figure's texts (title, legend entries, the names of its data files,
# numbers) are in NAME_labels.tsv, one a line: what it is, a tab, and its
# UTF-8 bytes in hexadecimal after an 'x' (so that no character of a name is
# ever read as gnuplot code; `cut -f2 NAME_labels.tsv | cut -c2- | xxd -r -p`
# shows them). To change one, set it again after it is read below.
reset session
set encoding utf8
name = ARG0[1:strlen(ARG0) - 3]
hex_digit(c) = strstrt("0123456789abcdef", c) - 1
hex_byte(h) = sprintf("%c", 16*hex_digit(h[1:1]) + hex_digit(h[2:2]))
hex_half(h) = 2*int(strlen(h)/4)
from_hex(h) = strlen(h) < 2 ? "" : strlen(h) == 2 ? hex_byte(h) : from_hex(h[1:hex_half(h)]).from_hex(h[hex_half(h)+1:])
set datafile separator "\t"
set datafile commentschars ""
set datafile nocolumnheaders
stats name."_labels.tsv" using (0) nooutput
array TEXT[STATS_records]
k = 0
stats name."_labels.tsv" using (k = k + 1, TEXT[k] = strcol(2), 0) nooutput
given_text(k) = from_hex(TEXT[k][2:])
given_number(k) = real(given_text(k))
set datafile separator ","
set datafile commentschars "#"
set datafile columnheaders
)";

// gnuplot on the PATH, looked up once (empty: none).
const fs::path& gnuplot_program() {
  static const fs::path program = [] {
    auto found = find_on_path("gnuplot");
    if (found.empty())
      log::info("gnuplot not found: no figures drawn, their scripts written (install gnuplot-nox, then run "
                "`gnuplot NAME.gp` in the output folder)");
    return found;
  }();
  return program;
}

// gnuplot started on `scripts` (run in turn) in `folder`, its messages
// appended to folder/gnuplot.log; its process id, or -1 if it could not be
// started. Started directly from an argument vector (no shell; not
// std::system, which ignores SIGINT in the caller while it waits): a Ctrl-C,
// which gnuplot answers by exiting with status 1, reaches this run as well.
pid_t start_gnuplot(const fs::path& folder, const std::vector<std::string>& scripts) {
  posix_spawn_file_actions_t files;
  if (posix_spawn_file_actions_init(&files) != 0) return -1;
  const std::string dir = folder.string();
  bool ok = posix_spawn_file_actions_addchdir_np(&files, dir.c_str()) == 0 &&
            posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0) == 0 &&
            posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0) == 0 &&
            posix_spawn_file_actions_addopen(&files, STDERR_FILENO, "gnuplot.log", O_WRONLY | O_CREAT | O_APPEND,
                                             0644) == 0;
  const std::string program = gnuplot_program().string();
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const auto& s : scripts) argv.push_back(const_cast<char*>(s.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  ok = ok && posix_spawn(&pid, program.c_str(), &files, nullptr, argv.data(), environ) == 0;
  posix_spawn_file_actions_destroy(&files);
  return ok ? pid : -1;
}

// The wait status of a gnuplot start_gnuplot started, or -1 (not started, or not waited for).
int wait_gnuplot(pid_t pid) {
  if (pid < 0) return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return status;
}

int run_gnuplot(const fs::path& folder, const std::vector<std::string>& scripts) {
  return wait_gnuplot(start_gnuplot(folder, scripts));
}

std::string tail_of(const fs::path& file, std::size_t bytes) {
  std::ostringstream read;
  read << std::ifstream(file, std::ios::binary).rdbuf();
  std::string text = read.str();
  if (text.size() > bytes) text = "…" + text.substr(text.size() - bytes);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  for (auto& c : text)
    if (c == '\n') c = ' ';
  return text;
}

// A whole PNG: the signature, and the IEND chunk closing it (gnuplot exits 0
// even when the disk filled up under it, leaving a truncated image).
bool complete_png(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[8] = {}, tail[12] = {};
  if (!in.read(head, 8) || std::string_view(head, 8) != "\x89PNG\r\n\x1a\n") return false;
  in.seekg(-12, std::ios::end);
  return in.read(tail, 12) && std::string_view(tail + 4, 8) == "IEND\xae\x42\x60\x82";
}

// A whole PDF: its header, and the %%EOF marker closing it.
bool complete_pdf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[5] = {};
  if (!in.read(head, 5) || std::string_view(head, 5) != "%PDF-") return false;
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::streamoff>(in.tellg());
  const std::streamoff n = std::min<std::streamoff>(size, 32);
  std::string tail(static_cast<std::size_t>(n), '\0');
  in.seekg(-n, std::ios::end);
  return in.read(tail.data(), n) && tail.find("%%EOF") != std::string::npos;
}

// A PDF that is the same bytes for the same figure: cairo stamps the time it
// was drawn into the PDF's /CreationDate (D:YYYYMMDDHHMMSSZ); that stamp is
// set to 1970-01-01 in place, the same length, so that no offset of the
// file's cross-reference table moves (a resumed or repeated run then writes
// the same PDF, as it writes the same PNG; run.h5 keeps the run's time).
void fix_creation_date(const fs::path& file) {
  std::ostringstream read;
  read << std::ifstream(file, std::ios::binary).rdbuf();
  const std::string text = read.str();
  constexpr std::string_view key = "/CreationDate (", epoch = "D:19700101000000Z";
  const auto at = text.find(key);
  if (at == std::string::npos) return;
  const auto start = at + key.size(), end = text.find(')', start);
  if (end == std::string::npos || end - start != epoch.size() || text.compare(start, 2, "D:") != 0) return;
  std::fstream io(file, std::ios::in | std::ios::out | std::ios::binary);
  io.seekp(static_cast<std::streamoff>(start));
  io.write(epoch.data(), static_cast<std::streamsize>(epoch.size()));
}

bool drawn(const fs::path& scratch, const Figure& f) {
  return complete_png(scratch / (f.name + ".png")) && complete_pdf(scratch / (f.name + ".pdf"));
}

// A name of a figure's file or data: relative, inside its folder, never read
// by gnuplot as an option ("-e ...").
void check_relative(const fs::path& p, const std::string& what) {
  bool inside = !p.empty() && p.is_relative();
  for (const auto& part : p) inside = inside && part != ".." && part != ".";
  if (!inside || p.string().front() == '-')
    throw std::logic_error(fmt::format("figure {} '{}' is not a plain relative name", what, p.string()));
}

// The scratch folder of one drawing (<folder>/.figures.partial-<pid>): the
// scripts, their texts and (links to) their data under the names the scripts
// give them; gone when the drawing is.
class Scratch {
 public:
  explicit Scratch(const fs::path& folder) : dir_(partial_path(folder / "figures")) {
    std::error_code ec;
    fs::remove_all(dir_, ec);
    create_output_folder(dir_);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  const fs::path& dir() const { return dir_; }

 private:
  fs::path dir_;
};

// `source` at `target`: a hard link (no copy), or a copy where the file
// system has none.
void link_data(const fs::path& source, const fs::path& target) {
  std::error_code ec;
  fs::create_directories(target.parent_path(), ec);
  if (!fs::exists(source, ec)) return;  // gnuplot says what it misses; the figure is then left out
  if (fs::exists(target, ec)) return;   // another figure's data too
  fs::create_hard_link(source, target, ec);
  if (ec) {
    ec.clear();
    fs::copy_file(source, target, fs::copy_options::overwrite_existing, ec);
    if (ec) throw OutputError(fmt::format("cannot copy {} to {}: {}", source.string(), target.string(), ec.message()));
  }
}

// Moves a file drawn in the scratch folder to its final name in `folder`,
// with the folder's output set.
fs::path publish(const fs::path& drawn_file, const fs::path& folder) {
  const fs::path final_path = folder / drawn_file.filename();
  const fs::path partial = partial_path(final_path);
  std::error_code ec;
  fs::rename(drawn_file, partial, ec);
  if (ec) throw OutputError(fmt::format("cannot write {}: {}", final_path.string(), ec.message()));
  commit_file(partial, final_path);
  return final_path;
}

}  // namespace

std::size_t Figure::add(std::string what, std::string text) {
  texts.emplace_back(std::move(what), std::move(text));
  return texts.size();
}

// Scientific with a decimal point ("1.0000000000000000e+09"): gnuplot's real() refuses "1e9".
std::size_t Figure::add(std::string what, double value) {
  return add(std::move(what), std::isfinite(value) ? fmt::format("{:.16e}", value) : std::isnan(value) ? "nan"
                                                       : value > 0 ? "inf" : "-inf");
}

bool plotting_available() { return !gnuplot_program().empty(); }

// `text` in at most kMaxTextBytes bytes: whole, or cut before a character
// (never inside one's UTF-8 bytes) and ended with an ellipsis.
std::string_view within_text_bytes(std::string_view text, std::string& cut) {
  if (text.size() <= kMaxTextBytes) return text;
  const std::string_view ellipsis = "…";
  std::size_t end = kMaxTextBytes - ellipsis.size();
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;  // a continuation byte
  cut.assign(text.substr(0, end));
  cut += ellipsis;
  return cut;
}

std::string figure_texts_file(const Figure& figure) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out, cut;
  for (const auto& [what, whole] : figure.texts) {
    for (char c : what) out += c == '\t' || c == '\n' || c == '\r' ? ' ' : c;
    out += "\tx";
    for (const char c : within_text_bytes(whole, cut)) {
      const auto b = static_cast<unsigned char>(c);
      out += digits[b >> 4];
      out += digits[b & 15];
    }
    out += '\n';
  }
  return out;
}

std::string figure_script(const Figure& figure) {
  std::string out(kPrologue);
  out += figure.script;
  if (!out.empty() && out.back() != '\n') out += '\n';
  return out;
}

std::string figure_text(std::string_view text, std::size_t max_chars, bool lines) {
  std::string out;
  std::size_t chars = 0;
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    std::size_t n = b < 0x80 ? 1 : (b & 0xE0) == 0xC0 ? 2 : (b & 0xF0) == 0xE0 ? 3 : (b & 0xF8) == 0xF0 ? 4 : 0;
    bool valid = n > 0 && i + n <= text.size() && !(n == 2 && b < 0xC2);
    for (std::size_t k = 1; valid && k < n; ++k) valid = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
    if (chars == max_chars) {
      out += "…";
      return out;
    }
    if (!valid) {
      out += "\uFFFD";
      i += 1;
    } else if (n == 1 && (b < 0x20 || b == 0x7F)) {
      out += b == '\n' && lines ? '\n' : ' ';
      i += 1;
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
    ++chars;
  }
  return out;
}

std::vector<fs::path> draw_figures(const fs::path& folder, const std::vector<Figure>& figures) {
  std::vector<fs::path> written;
  if (figures.empty()) return written;
  const Scratch scratch(folder);
  std::vector<std::string> scripts;
  for (const auto& f : figures) {
    check_relative(f.name, "name");
    if (f.name.find('/') != std::string::npos || f.name.front() == '.')
      throw std::logic_error("figure name '" + f.name + "' is not a plain file name");
    write_temporary_file(scratch.dir() / (f.name + ".gp"), figure_script(f));
    write_temporary_file(scratch.dir() / (f.name + "_labels.tsv"), figure_texts_file(f));
    for (const auto& d : f.data) {
      check_relative(d, "data file");
      link_data(OutputSet::readable(folder / d), scratch.dir() / d);
    }
    scripts.push_back(f.name + ".gp");
  }
  std::vector<bool> ok(figures.size(), false);
  if (plotting_available()) {
    auto interrupted = [](int status) { return (status != -1 && WIFSIGNALED(status)) || interrupt_requested(); };
    // Several figures (the end of a sweep, when nothing else runs): two
    // gnuplots side by side, each drawing every other figure in turn.
    std::vector<std::string> group[2];
    for (std::size_t k = 0; k < scripts.size(); ++k) group[k % 2].push_back(scripts[k]);
    pid_t pid[2] = {-1, -1};
    for (int g = 0; g < 2; ++g)
      if (!group[g].empty()) pid[g] = start_gnuplot(scratch.dir(), group[g]);
    int status = 0;
    bool stopped = false;
    for (int g = 0; g < 2; ++g) {
      if (group[g].empty()) continue;
      const int s = wait_gnuplot(pid[g]);
      stopped = stopped || interrupted(s);
      if (s != 0 && (status == 0 || status == -1)) status = s;  // a failure's exit status before "not started"
    }
    if (stopped)  // the run stops too, so that it is not taken as complete without its figures
      throw Interrupted(fmt::format("gnuplot was stopped by a signal while drawing the figures of {}", folder.string()));
    std::string failure;
    if (status != 0) {
      failure = status == -1 ? "it could not be started" : fmt::format("exit status {}", WEXITSTATUS(status));
      // One figure that fails ends gnuplot: the others are drawn each on its own.
      for (std::size_t k = 0; k < figures.size() && status != -1; ++k)
        if (!drawn(scratch.dir(), figures[k])) {
          const int alone = run_gnuplot(scratch.dir(), {scripts[k]});
          if (interrupted(alone))
            throw Interrupted(fmt::format("gnuplot was stopped by a signal while drawing {}",
                                          (folder / figures[k].name).string()));
        }
    }
    for (std::size_t k = 0; k < figures.size(); ++k) {
      ok[k] = drawn(scratch.dir(), figures[k]);
      if (ok[k]) continue;
      if (status == 0)  // gnuplot said yes, but the file system did not take it all
        throw OutputError(fmt::format("cannot write {}: gnuplot left an incomplete image (is the disk full?); it was "
                                      "not written",
                                      (folder / (figures[k].name + ".png")).string()));
      log::warn("gnuplot could not draw {}.png ({}: {}); its script is kept: gnuplot {}.gp in {}",
                (folder / figures[k].name).string(), failure, tail_of(scratch.dir() / "gnuplot.log", 300),
                figures[k].name, folder.string());
    }
  }
  for (std::size_t k = 0; k < figures.size(); ++k) {
    const auto& f = figures[k];
    written.push_back(publish(scratch.dir() / (f.name + ".gp"), folder));
    written.push_back(publish(scratch.dir() / (f.name + "_labels.tsv"), folder));
    if (ok[k]) {
      fix_creation_date(scratch.dir() / (f.name + ".pdf"));
      written.push_back(publish(scratch.dir() / (f.name + ".png"), folder));
      written.push_back(publish(scratch.dir() / (f.name + ".pdf"), folder));
    }
  }
  return written;
}

}  // namespace wearscale::coupling
