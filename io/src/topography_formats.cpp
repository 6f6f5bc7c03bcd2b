// What the readers of measured topographies share: the raw grid, bounds-
// checked binary fields, units of length.
#include "topography_formats.hpp"

#include <bit>
#include <cctype>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/memory_limit.hpp"

namespace wearscale::bem::formats {

void refuse(const std::string& where, const std::string& problem) {
  throw InputError(fmt::format("{}: {}", where, problem));
}

std::optional<std::size_t> product(std::size_t a, std::size_t b) {
  if (a != 0 && b > std::numeric_limits<std::size_t>::max() / a) return std::nullopt;
  return a * b;
}

void RawTopography::allocate(std::size_t nx_, std::size_t ny_, std::size_t max_points) {
  if (nx_ == 0 || ny_ == 0) refuse(where, fmt::format("a grid of {} × {} points holds no data", nx_, ny_));
  const auto n = product(nx_, ny_);
  if (!n || *n > max_points)
    refuse(where, fmt::format("a grid of {} × {} points is larger than allowed (at most {} points)", nx_, ny_,
                              max_points));
  require_memory(25.0 * static_cast<double>(*n), fmt::format("{} ({} × {} heights)", where, nx_, ny_));
  nx = nx_, ny = ny_;
  height.assign(*n, 0.0);
  missing.clear();
}

void RawTopography::mark_missing(std::size_t i, std::size_t j) {
  if (missing.empty()) missing.assign(height.size(), 0);
  missing[i * ny + j] = 1;
}

// ------------------------------------------------------------- bytes ---

void Bytes::seek(std::size_t p, const char* what) {
  if (p > data_.size())
    refuse(where_, fmt::format("the file ends at byte {} inside {} (needs {} bytes)", data_.size(), what, p));
  pos_ = p;
}

std::string_view Bytes::take(std::size_t n, const char* what) {
  if (n > data_.size() - pos_)
    refuse(where_, fmt::format("the file ends at byte {} inside {} ({} more bytes needed at byte {})", data_.size(),
                               what, n, pos_));
  const auto out = data_.substr(pos_, n);
  pos_ += n;
  return out;
}

namespace {
template <class U>
U unsigned_field(Bytes& b, bool big, const char* what) {
  const auto raw = b.take(sizeof(U), what);
  U v = 0;
  for (std::size_t k = 0; k < sizeof(U); ++k) {
    const auto byte = static_cast<U>(static_cast<unsigned char>(raw[big ? k : sizeof(U) - 1 - k]));
    v = static_cast<U>((v << 8) | byte);
  }
  return v;
}
}  // namespace

std::uint8_t Bytes::u8(const char* what) { return static_cast<std::uint8_t>(take(1, what)[0]); }
std::uint16_t Bytes::u16(const char* what) { return unsigned_field<std::uint16_t>(*this, big_, what); }
std::uint32_t Bytes::u32(const char* what) { return unsigned_field<std::uint32_t>(*this, big_, what); }
std::uint64_t Bytes::u64(const char* what) { return unsigned_field<std::uint64_t>(*this, big_, what); }
double Bytes::f32(const char* what) { return static_cast<double>(std::bit_cast<float>(u32(what))); }
double Bytes::f64(const char* what) { return std::bit_cast<double>(u64(what)); }

std::string Bytes::cstring(const char* what) {
  const auto end = data_.find('\0', pos_);
  if (end == std::string_view::npos)
    refuse(where_, fmt::format("the file ends inside {} (a string without its terminating NUL at byte {})", what,
                               pos_));
  std::string out(data_.substr(pos_, end - pos_));
  pos_ = end + 1;
  return out;
}

std::string trimmed_field(std::string_view raw) {
  const auto nul = raw.find('\0');
  if (nul != std::string_view::npos) raw = raw.substr(0, nul);
  while (!raw.empty() && (raw.back() == ' ' || raw.back() == '\t')) raw.remove_suffix(1);
  while (!raw.empty() && (raw.front() == ' ' || raw.front() == '\t')) raw.remove_prefix(1);
  return std::string(raw);
}

std::optional<double> metres_per(std::string_view unit) {
  std::string u;
  for (std::size_t k = 0; k < unit.size(); ++k) {
    const auto c = static_cast<unsigned char>(unit[k]);
    if (c == ' ' || c == '\t') continue;
    // The micro sign in its spellings: UTF-8 µ (C2 B5) and μ (CE BC), Latin-1 B5, MS-DOS code page E6.
    if ((c == 0xC2 && k + 1 < unit.size() && static_cast<unsigned char>(unit[k + 1]) == 0xB5) ||
        (c == 0xCE && k + 1 < unit.size() && static_cast<unsigned char>(unit[k + 1]) == 0xBC)) {
      u += 'u';
      ++k;
    } else if (c == 0xB5 || c == 0xE6) {
      u += 'u';
    } else if (c == 0xC3 && k + 1 < unit.size() && static_cast<unsigned char>(unit[k + 1]) == 0x85) {
      u += "angstrom";  // Å in UTF-8 (a plain A is an ampere)
      ++k;
    } else if (c == 0xC5) {
      u += "angstrom";  // Å in Latin-1
    } else {
      u += static_cast<char>(std::tolower(c));
    }
  }
  static const std::pair<const char*, double> table[] = {
      {"m", 1.0},          {"meter", 1.0},       {"meters", 1.0},     {"metre", 1.0},      {"metres", 1.0},
      {"mm", 1e-3},        {"millimeters", 1e-3}, {"millimetres", 1e-3}, {"um", 1e-6},   {"micron", 1e-6},
      {"microns", 1e-6},   {"micrometers", 1e-6}, {"micrometres", 1e-6}, {"nm", 1e-9},   {"nanometers", 1e-9},
      {"nanometres", 1e-9}, {"pm", 1e-12},       {"picometers", 1e-12}, {"angstrom", 1e-10},
      {"angstroms", 1e-10}, {"cm", 1e-2},        {"km", 1e3}};
  for (const auto& [name, factor] : table)
    if (u == name) return factor;
  return std::nullopt;
}

}  // namespace wearscale::bem::formats
