#pragma once
// Reading a text input (case file, strength table, topography grid, summary)
// whole, safely: only a regular file (not /dev/zero, a FIFO or a folder),
// no larger than a bound stated by the caller, with a UTF-8 byte-order mark
// (as spreadsheet programs write) removed.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace wearscale {

/// The content of `file`. InputError naming the file if it is missing, not a
/// regular file, unreadable, or larger than `max_bytes` (`what` names the
/// kind of file in messages: "case file", "strength table").
std::string read_text_file(const std::filesystem::path& file, std::string_view what, std::uintmax_t max_bytes);

/// `text` without a leading UTF-8 byte-order mark (EF BB BF).
std::string_view strip_utf8_bom(std::string_view text);

}  // namespace wearscale
