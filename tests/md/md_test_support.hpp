#pragma once
// Helpers of the md tests: temporary folders, a fake `lmp` script.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include "scratch_dir.hpp"

namespace md_test {

/// A fresh folder under the system temp folder, unique to this process and name.
inline std::filesystem::path temp_dir(const std::string& name) {
  static const ScratchDir d_scratch("wearscale-md-test-");
  const std::filesystem::path d = d_scratch.path() / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

inline void write(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

inline std::string read(const std::filesystem::path& p) {
  std::stringstream ss;
  ss << std::ifstream(p).rdbuf();
  return ss.str();
}

/// Whether `text` has a line whose whitespace-separated words start with `words`.
inline bool has_line(const std::string& text, const std::string& words) {
  auto norm = [](const std::string& s) {
    std::stringstream ss(s);
    std::string w, out;
    while (ss >> w) out += (out.empty() ? "" : " ") + w;
    return out;
  };
  const std::string want = norm(words);
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line))
    if (norm(line).rfind(want, 0) == 0) return true;
  return false;
}

/// The Stillinger–Weber Si parameters (as in LAMMPS' Si.sw), for tests that
/// must not depend on an installed LAMMPS.
inline const char* si_sw = "Si Si Si 2.1683 2.0951 1.80 21.0 1.20 -0.333333333333\n"
                           "         7.049556277 0.6022245584 4.0 0.0 0.0\n";

/// The rows an elastic-constants deck prints (elastic_constants.hpp) for a
/// cubic solid of C11, C12, C44 [GPa] at strain 1e-3: P = −C ε, in bar.
inline std::string elastic_rows(double c11, double c12, double c44) {
  const double c[6][6] = {{c11, c12, c12, 0, 0, 0}, {c12, c11, c12, 0, 0, 0}, {c12, c12, c11, 0, 0, 0},
                          {0, 0, 0, c44, 0, 0},     {0, 0, 0, 0, c44, 0},     {0, 0, 0, 0, 0, c44}};
  std::string rows = "0 0 0 0 0 0 0 0 0 16.293 16.293 16.293\n";
  int k = 1;
  for (int j = 0; j < 6; ++j)
    for (int sign : {1, -1}) {
      rows += std::to_string(k++) + " " + std::to_string(j + 1) + " " + std::to_string(sign);
      for (int i = 0; i < 6; ++i) rows += " " + std::to_string(-sign * 1e-3 * c[i][j] * 1e4);  // GPa → bar
      rows += " 16.293 16.293 16.293\n";
    }
  return rows;
}

/// A fake lmp: appends one line per call to `counter`; `-h` prints a version
/// line; an elastic-constants deck gets the rows of Stillinger–Weber Si
/// (C11 = 151.4, C12 = 76.4, C44 = 56.4 GPa); otherwise writes a synthetic
/// shear.dat (peak 12 GPa at strain 0.3, 2 GPa after) and sample.txt into the
/// current folder, like the real deck.
inline std::filesystem::path fake_lmp(const std::filesystem::path& dir, const std::filesystem::path& counter) {
  const auto p = dir / "lmp";
  std::string s = "#!/bin/sh\necho \"$@\" >> '" + counter.string() + "'\n";
  s += "if [ \"$1\" = \"-h\" ]; then echo 'Large-scale Atomic/Molecular Massively Parallel Simulator - 1 Jan 2000 - fake'; exit 0; fi\n";
  s += "if grep -q elastic.txt in.lammps; then cat > elastic.txt <<'EOF'\n" + elastic_rows(151.4, 76.4, 56.4) +
       "EOF\nprintf 'atoms 216\\ncompleted yes\\n' > sample.txt; exit 0; fi\n";
  s += "echo '# Time-averaged data for fix curve' > shear.dat\n";
  s += "echo '# TimeStep v_strain v_tau v_p_n v_h c_t_mobile' >> shear.dat\n";
  s += "i=1; while [ $i -le 60 ]; do\n"
       "  if [ $i -le 30 ]; then tau=$(( i * 4 / 10 )); else tau=2; fi\n"
       "  echo \"$(( 2000 + 100 * i )) 0.$(printf %02d $i) $tau 0 19 300\" >> shear.dat\n"
       "  i=$(( i + 1 )); done\n";
  s += "printf 'atoms 544\\natoms_top 96\\natoms_bottom 96\\nlx_A 21.724\\nly_A 21.724\\nh0_A 19.0\\n"
       "h_gap_A 15.0\\nshear_steps 11400\\nfirst_step 2000\\ncompleted yes\\n' > sample.txt\n";
  write(p, s);
  std::filesystem::permissions(p, std::filesystem::perms::owner_all);
  return p;
}

}  // namespace md_test
