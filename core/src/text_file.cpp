#include "wearscale/core/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/memory_limit.hpp"

namespace wearscale {

std::string_view strip_utf8_bom(std::string_view text) {
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  return text;
}

std::string read_text_file(const std::filesystem::path& file, std::string_view what, std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  const std::string name = file.string();
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (ec || !fs::exists(status)) throw InputError(fmt::format("{}: no such {}", name, what));
  if (fs::is_directory(status)) throw InputError(fmt::format("{}: is a directory, expected a {}", name, what));
  if (!fs::is_regular_file(status))
    throw InputError(fmt::format("{}: not a regular file (a device, FIFO or socket); expected a {}", name, what));
  const auto size = fs::file_size(file, ec);
  if (ec) throw InputError(fmt::format("{}: cannot read the {}: {}", name, what, ec.message()));
  if (size > max_bytes)
    throw InputError(fmt::format("{}: {}, larger than a {} may be ({} at most)", name,
                                 format_bytes(static_cast<double>(size)), what,
                                 format_bytes(static_cast<double>(max_bytes))));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open the {} for reading: {}", name, what, std::strerror(errno)));
  std::string content(static_cast<std::size_t>(size), '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  if (in.bad() || static_cast<std::uintmax_t>(in.gcount()) != size)
    throw InputError(fmt::format("{}: cannot read the {}: {}", name, what, std::strerror(errno)));
  const auto body = strip_utf8_bom(content);
  if (body.size() != content.size()) content.erase(0, content.size() - body.size());
  return content;
}

}  // namespace wearscale
