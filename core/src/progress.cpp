#include "wearscale/core/progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

#include "wearscale/core/log.hpp"

namespace wearscale {

namespace {
std::string format_duration(double s) {
  if (!std::isfinite(s)) return "--";
  const long t = std::lround(s);
  if (t >= 3600) return fmt::format("{}h{:02}m", t / 3600, (t % 3600) / 60);
  if (t >= 60) return fmt::format("{}m{:02}s", t / 60, t % 60);
  return fmt::format("{}s", t);
}
}  // namespace

bool Progress::terminal_is_interactive() {
  const char* ci = std::getenv("CI");
  const bool in_ci = ci != nullptr && *ci != '\0' && std::string(ci) != "false" && std::string(ci) != "0";
  return !in_ci && ::isatty(STDERR_FILENO) != 0 && log::level() != log::Level::Quiet;
}

Progress::Progress(std::string label, double total, std::string unit)
    : Progress(std::move(label), total, std::move(unit), terminal_is_interactive()) {}

Progress::Progress(std::string label, double total, std::string unit, bool enabled)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total), enabled_(enabled), start_(clock::now()),
      last_draw_(start_) {}

Progress Progress::silent(double total) { return Progress("", total, "steps", false); }

Progress::~Progress() { finish(); }

double Progress::rate() const {
  const double s = std::chrono::duration<double>(clock::now() - start_).count();
  return s > 0 ? (done_ - base_) / s : 0.0;
}

void Progress::start_at(double done) {
  base_ = done;
  done_ = done;
  start_ = clock::now();
}

double Progress::eta_seconds() const {
  const double r = rate();
  if (!(r > 0)) return std::nan("");
  return std::max(0.0, total_ - done_) / r;
}

std::string Progress::line() const {
  const double pct = total_ > 0 ? 100.0 * done_ / total_ : 0.0;
  const double elapsed = std::chrono::duration<double>(clock::now() - start_).count();
  if (!(done_ > base_) || elapsed < 0.5) return fmt::format("{}  {:3.0f}%  -- {}/s  ETA --", label_, pct, unit_);
  return fmt::format("{}  {:3.0f}%  {:.3g} {}/s  ETA {}", label_, pct, rate(), unit_, format_duration(eta_seconds()));
}

std::string Progress::fit_to_width(const std::string& text, std::size_t columns) {
  std::size_t points = 0;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if ((static_cast<unsigned char>(text[k]) & 0xC0) == 0x80) continue;  // a continuation byte
    if (points++ == columns) return text.substr(0, k);
  }
  return text;
}

std::size_t Progress::terminal_columns() {
  winsize w{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 0) return w.ws_col;
  return 80;
}

void Progress::update(double done) {
  done_ = done;
  if (!enabled_) return;
  const auto now = clock::now();
  if (drawn_ && now - last_draw_ < std::chrono::milliseconds(200) && done_ < total_) return;
  last_draw_ = now;
  drawn_ = true;
  // One column short of the width: a full-width line wraps on some terminals.
  const std::string text = fit_to_width(line(), std::max<std::size_t>(terminal_columns(), 2) - 1);
  std::fprintf(stderr, "\r\033[K%s", text.c_str());
  std::fflush(stderr);
  log::set_status_line(true);
}

void Progress::finish() {
  if (!enabled_ || !drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  log::set_status_line(false);
  drawn_ = false;
}

}  // namespace wearscale
