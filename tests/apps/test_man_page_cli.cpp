// The man page the build makes (cmake/WearscaleCliDocs.cmake: help2man over
// --help-all, then preconv): every non-ASCII character of the help (µ, ν, ≥,
// §, …) is in the page as the character or as its groff escape \[uXXXX],
// none lost to '?' as help2man did in its default C locale. Reads two files:
// milliseconds. Skipped when the build had no help2man.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <fmt/format.h>

namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The code points above U+007F of UTF-8 `text`, each with its bytes.
std::set<std::pair<char32_t, std::string>> non_ascii(const std::string& text) {
  std::set<std::pair<char32_t, std::string>> out;
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    const std::size_t n = b < 0x80 ? 1 : b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : 2;
    if (n > 1) {
      char32_t c = b & (0x3F >> (n - 1));
      for (std::size_t k = 1; k < n && i + k < text.size(); ++k) c = (c << 6) | (text[i + k] & 0x3F);
      out.insert({c, text.substr(i, n)});
    }
    i += n;
  }
  return out;
}
}  // namespace

TEST(ManPage, KeepsEveryCharacterOfTheHelp) {
  const fs::path page = fs::path(WEARSCALE_HELP_ALL).parent_path() / "man1" / "wearscale.1";
  if (!fs::exists(page)) GTEST_SKIP() << "no " << page << ": the build found no help2man (apt install help2man)";
  const std::string man = slurp(page), help = slurp(WEARSCALE_HELP_ALL);
  EXPECT_EQ(man.find("??"), std::string::npos) << "a character lost to '?' in " << page;
  const auto chars = non_ascii(help);
  EXPECT_GE(chars.size(), 5u) << "the help has µ, ν, ≥, § and more: is " << WEARSCALE_HELP_ALL << " the help?";
  for (const auto& [code, bytes] : chars) {
    const std::string escape = fmt::format("\\[u{:04X}]", static_cast<unsigned>(code));
    EXPECT_TRUE(man.find(escape) != std::string::npos || man.find(bytes) != std::string::npos)
        << bytes << " (U+" << fmt::format("{:04X}", static_cast<unsigned>(code)) << ") is in the help, not in " << page;
  }
}
