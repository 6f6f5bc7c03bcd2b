#include "wearscale/md/potential_file.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::md {

std::filesystem::path lammps_potentials_dir() {
  if (const char* env = std::getenv("LAMMPS_POTENTIALS"); env != nullptr && *env != '\0') return env;
  return "/usr/share/lammps/potentials";
}

std::filesystem::path find_potential_file(const std::filesystem::path& name) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(name, ec)) return std::filesystem::absolute(name);
  const auto in_dir = lammps_potentials_dir() / name;
  if (name.is_relative() && std::filesystem::is_regular_file(in_dir, ec)) return in_dir;
  throw InputError(fmt::format(
      "potential file '{}' not found (looked for it as given and in {}); the LAMMPS potentials come with "
      "Debian's lammps-data package: apt-get install lammps",
      name.string(), lammps_potentials_dir().string()));
}

std::string read_text_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot read file", file.string()));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string vashishta_with_cutoff(const std::string& text, double cutoff_angstrom, const std::string& origin) {
  // Tokenise without comments, remembering where each token sits so the
  // rewritten file keeps the original layout.
  struct Token {
    std::size_t begin, end;
  };
  std::vector<Token> tokens;
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n) {
    const char c = text[i];
    if (c == '#') {
      while (i < n && text[i] != '\n') ++i;
    } else if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      ++i;
    } else {
      const std::size_t b = i;
      while (i < n && text[i] != ' ' && text[i] != '\t' && text[i] != '\n' && text[i] != '\r' && text[i] != '#') ++i;
      tokens.push_back({b, i});
    }
  }
  constexpr std::size_t fields = 17, rc_field = 11;
  if (tokens.empty() || tokens.size() % fields != 0)
    throw InputError(fmt::format("{}: not a Vashishta potential file: {} fields, expected a multiple of {}", origin,
                                 tokens.size(), fields));
  std::string out = fmt::format(
      "# Written by wearscale from {}:\n# the two-body cutoff rc of every entry set to {:g} Angstrom (thesis "
      "Sec. 2.1.3, Luo et al. 2016); all other parameters unchanged.\n",
      origin, cutoff_angstrom);
  std::size_t copied = 0;
  int changed = 0;
  for (std::size_t e = 0; e < tokens.size() / fields; ++e) {
    for (std::size_t f = 3; f < fields; ++f) {
      const Token& t = tokens[e * fields + f];
      const std::string s = text.substr(t.begin, t.end - t.begin);
      char* endp = nullptr;
      std::strtod(s.c_str(), &endp);
      if (endp == s.c_str() || *endp != '\0')
        throw InputError(fmt::format("{}: not a Vashishta potential file: entry {} field {} is '{}', not a number",
                                     origin, e + 1, f + 1, s));
    }
    const Token& rc = tokens[e * fields + rc_field];
    const double old_rc = std::strtod(text.substr(rc.begin, rc.end - rc.begin).c_str(), nullptr);
    if (old_rc == 0.0) continue;
    out.append(text, copied, rc.begin - copied);
    out += fmt::format("{:g}", cutoff_angstrom);
    copied = rc.end;
    ++changed;
  }
  out.append(text, copied, std::string::npos);
  if (changed == 0) throw InputError(fmt::format("{}: no Vashishta entry has a non-zero cutoff rc", origin));
  return out;
}

}  // namespace wearscale::md
