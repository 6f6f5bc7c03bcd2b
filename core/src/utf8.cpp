#include "wearscale/core/utf8.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "wearscale/core/errors.hpp"

namespace wearscale {

// nlohmann::json validates UTF-8 when it serialises a string; that check is the
// one every JSON output meets, so it is the one used here.
bool is_utf8(std::string_view text) {
  try {
    (void)nlohmann::json(std::string(text)).dump();
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

std::string quoted_for_message(std::string_view text) {
  return nlohmann::json(std::string(text)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void require_utf8_path(const std::filesystem::path& path, std::string_view what) {
  if (!is_utf8(path.string()))
    throw InputError(fmt::format("{} {}: the path is not valid UTF-8 (shown with U+FFFD where a byte is not); "
                                 "allowed: a UTF-8 path",
                                 what, quoted_for_message(path.string())));
}

}  // namespace wearscale
