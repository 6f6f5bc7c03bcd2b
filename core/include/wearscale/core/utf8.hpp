#pragma once
// Whether text is valid UTF-8, the only encoding the JSON outputs (summaries,
// results, fingerprints) can hold: strings and paths from the command line are
// checked on the way in, so that no output fails half written.
#include <filesystem>
#include <string>
#include <string_view>

namespace wearscale {

/// True when `text` is valid UTF-8.
bool is_utf8(std::string_view text);

/// `text` for a message: as JSON would quote it, with U+FFFD where a byte is not UTF-8.
std::string quoted_for_message(std::string_view text);

/// InputError unless `path` is valid UTF-8 (`what` names it: "--out", "case file").
void require_utf8_path(const std::filesystem::path& path, std::string_view what);

}  // namespace wearscale
