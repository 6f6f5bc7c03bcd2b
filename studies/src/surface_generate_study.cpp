// The surface-generation study ([surface.generate]): a periodic rough surface
// with the PSD of thesis Fig. 1.3 (plateau k_l…k_r, slope −2(H+1) from k_r to
// k_s, §1.1.2), rescaled to one roughness target (h'_RMS (1.6), h_RMS (1.5)
// or Sa (1.4)), written as HDF5 (dataset /surface/height, with its generation
// parameters as attributes) + XDMF into the output folder.
//
//   [surface.generate]
//   n = 512              # or nx, ny
//   size = "100 um"      # or "Lx,Ly", [Lx, Ly]
//   hurst = 0.8
//   k_l = 4              # k_r defaults to k_l (no plateau)
//   k_s = 64
//   hprime_rms = 0.2     # or h_rms, sa
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "surface_sides.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/io/topography_io.hpp"
#include "wearscale/io/key_table.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies {

namespace {

const Range grid_points = Range::closed(4, 65536);

// [surface.generate]: the grid, the sides, the spectrum, one roughness target and the file.
struct SurfaceGenerateKeys {
  long n = 0, nx = 0, ny = 0;     // grid points (0: not given)
  bem::TopographySize size;       // the sides (lx not given: none)
  bem::RoughSurfaceSpec surface;  // H, k_l, k_r, k_s, seed; its grid from n, nx, ny and size
  std::optional<double> hprime_rms, h_rms, sa;
  std::string file = "surface.h5";
  // Not keys: the target the three give, checked against the spectrum.
  bem::RoughnessMeasure measure = bem::RoughnessMeasure::HPrimeRms;
  double target = 0.0;
};

// A side of the grid: the key when given (in 4 … 65536), else `fallback`.
long grid_side(const Config& c, const std::string& key, long fallback) {
  return c.has(key) ? c.integer(key, grid_points) : fallback;
}

const KeyTable<SurfaceGenerateKeys>& surface_generate_keys() {
  using K = SurfaceGenerateKeys;
  const auto side = [](const K& k) { return std::min(*k.size.lx, k.size.ly.value_or(*k.size.lx)); };
  static const auto table =
      KeyTable<K>()
          .custom("n", "integer", grid_points.describe(), "", "points per side of a square grid",
                  [](const Config& c, const std::string& key, K& k) { k.n = grid_side(c, key, 0); })
          .flag("--n")
          .custom("nx", "integer", grid_points.describe(), "", "points along x",  // --nx, --ny override --n
                  [](const Config& c, const std::string& key, K& k) { k.nx = grid_side(c, key, k.n); })
          .fallback("n")
          .flag("--nx")
          .custom("ny", "integer", grid_points.describe(), "", "points along y",
                  [](const Config& c, const std::string& key, K& k) { k.ny = grid_side(c, key, k.n); })
          .fallback("n")
          .flag("--ny")
          .then([](const Config& c, K& k) {
            if (k.nx == 0 || k.ny == 0)
              throw c.error("n", "the grid is not given", "n (square; --n) or nx and ny (--nx, --ny)");
          })
          .custom("size", "number", "> 0", "m", "side L of the square surface (\"100 um\" also works), or Lx,Ly",
                  [](const Config& c, const std::string& key, K& k) { k.size = read_sides(c, key); })
          .flag("--size")
          .then([](const Config& c, K& k) {
            if (!k.size.lx) throw c.error("size", "the side of the surface is not given", "a positive length (--size)");
          })
          // H and 0 < k_l ≤ k_r ≤ k_s ≤ Nyquist: checked by bem::validate once all are read.
          .number("hurst", [](K& k) -> double& { return k.surface.hurst; }, Range::any(), "Hurst exponent H")
          .required()
          .allowed("(0, 1]")
          .flag("--hurst")
          .number("k_l", [](K& k) -> double& { return k.surface.k_l; }, Range::any(),
                  "wavenumber of the longest wavelength, q_l = 2π k_l / L")
          .required()
          .allowed("(0, k_r]")
          .flag("--kl")
          .number("k_r", [](K& k) -> double& { return k.surface.k_r; }, Range::any(),
                  "roll-off wavenumber (k_l: no plateau)")
          .computed_default([](const K& k) { return k.surface.k_l; }, "k_l")
          .allowed("[k_l, k_s]")
          .flag("--kr")
          .number("k_s", [](K& k) -> double& { return k.surface.k_s; }, Range::any(),
                  "wavenumber of the shortest wavelength")
          .required()
          .allowed("[k_r, min(nx, ny)/2]")
          .flag("--ks")
          .integer("seed", [](K& k) -> std::uint64_t& { return k.surface.seed; }, Range::non_negative(),
                   "seed of the random phases (same seed, same surface)")
          .flag("--seed")
          .then([](const Config& c, K& k) {
            const double lx = *k.size.lx, ly = k.size.ly.value_or(lx);
            k.surface.grid = Grid2D(static_cast<std::size_t>(k.nx), static_cast<std::size_t>(k.ny), lx, ly);
            // The library's message is named after the key that was given.
            try {
              bem::validate(k.surface);
            } catch (const InputError& e) {
              const std::string m = e.what();
              for (const char* p : {"hurst", "k_l", "k_r", "k_s"})
                if (m.find(fmt::format("'{}'", p)) != std::string::npos)
                  throw InputError(fmt::format("{}: {} (key {})", c.where(p), m, c.full_key(p)));
              throw;
            }
            const int targets = int(c.has("hprime_rms")) + int(c.has("h_rms")) + int(c.has("sa"));
            if (targets != 1)
              throw c.error("hprime_rms", fmt::format("give exactly one of hprime_rms, h_rms, sa (got {})", targets),
                            "one roughness target (--hprime-rms, --h-rms, --sa)");
          })
          // Bounds that keep every derived figure finite and the surface a surface: an RMS slope up to 100
          // (the BEM assumes small slopes: ≲ 1), heights up to the side of the surface.
          .optional_number("hprime_rms", &K::hprime_rms, Range::open_closed(0.0, bem::max_hprime_rms),
                           units::dimensionless, "rescale to this RMS slope h'_RMS (1.6); one of three")
          .flag("--hprime-rms")
          .optional_number("h_rms", &K::h_rms, Range::positive(), units::length,
                           "rescale to this RMS height h_RMS (1.5)")
          .range_from([side](const K& k) { return Range::open_closed(0.0, side(k)); }, "(0, side]")
          .flag("--h-rms")
          .optional_number("sa", &K::sa, Range::positive(), units::length,
                           "rescale to this arithmetic mean deviation Sa (1.4)")
          .range_from([side](const K& k) { return Range::open_closed(0.0, side(k)); }, "(0, side]")
          .flag("--sa")
          .then([](const Config& c, K& k) {
            // The slope an h_RMS or Sa target gives on this spectrum, within the same bound
            // (bem::check_roughness_target, as contact.rough's).
            const char* key = k.hprime_rms ? "hprime_rms" : k.h_rms ? "h_rms" : "sa";
            k.measure = k.hprime_rms ? bem::RoughnessMeasure::HPrimeRms
                        : k.h_rms    ? bem::RoughnessMeasure::HRms
                                     : bem::RoughnessMeasure::Sa;
            k.target = k.hprime_rms ? *k.hprime_rms : k.h_rms ? *k.h_rms : *k.sa;
            if (const auto p = bem::roughness_target_problem(k.surface, k.measure, k.target); !p.problem.empty())
              throw c.error(key, p.problem, p.allowed);
          })
          .checked_string("file", &K::file, "a file name ending in .h5",
                          "the surface's name in the output folder (an .xdmf sidecar beside it)",
                          [](const Config& c, const std::string& key, K& k) {
                            k.file = output_file_name(c, key, k.file, {".h5"});
                          })
          .flag("--file");
  return table;
}

class SurfaceGenerate final : public Study {
 public:
  std::string name() const override { return "surface/generate"; }
  std::string summary() const override {
    return "Generate a periodic rough surface with the PSD of thesis Fig. 1.3 (plateau k_l…k_r, slope −2(H+1) from "
           "k_r to k_s) and write it to HDF5 + XDMF";
  }
  std::string default_case_name() const override { return "surface"; }
  Schema schema() const override { return surface_generate_keys().schema("surface.generate"); }

  std::vector<std::string> prepare(Config& cfg) override {
    SurfaceGenerateKeys keys;
    surface_generate_keys().read(cfg.section("surface.generate"), keys);
    spec_ = keys.surface;
    measure_ = keys.measure;
    target_ = keys.target;
    file_ = keys.file;
    // The surface, its spectrum and the copy written out, before any is allocated.
    require_memory(48.0 * static_cast<double>(keys.nx) * static_cast<double>(keys.ny),
                   fmt::format("surface generate: a {} × {} surface", keys.nx, keys.ny),
                   "give a smaller --n (or --nx, --ny)");
    cfg.reject_unknown_keys();
    return {};
  }

  void run(const Config& /*cfg*/, RunContext& context) override {
    const RealField h = bem::generate_surface(spec_, measure_, target_);
    const double sa = bem::sa(h), h_rms = bem::h_rms(h), h_prime = bem::h_prime_rms(h);
    for (const auto& [name, v] : {std::pair{"Sa", sa}, std::pair{"h_rms", h_rms}, std::pair{"h'_rms", h_prime}})
      if (!std::isfinite(v) || !(v > 0.0))
        throw NumericalError("surface generate", 0, name, fmt::format("{} of the generated surface", v));
    const auto file = context.output_dir() / file_;
    const auto sidecar = bem::write_surface(file, h, bem::generation_attributes(spec_));
    context.add_file(file);
    context.add_file(sidecar);
    context.report("Sa", sa, "m", "arithmetic mean deviation Sa (1.4)");
    context.report("h_rms", h_rms, "m", "RMS height h_RMS (1.5)");
    context.report("h_prime_rms", h_prime, "1", "RMS slope h'_RMS (1.6), spectral");
    const Grid2D& g = spec_.grid;
    context.note("file", file.string());
    context.note("xdmf", sidecar.string());
    context.note("grid", {{"nx", g.nx}, {"ny", g.ny}, {"lx", g.lx}, {"ly", g.ly}});
    context.note("hurst", spec_.hurst);
    context.note("k_l", spec_.k_l);
    context.note("k_r", spec_.k_r);
    context.note("k_s", spec_.k_s);
    context.note("seed", spec_.seed);
    context.note("rescaled_to", {{"measure", bem::name(measure_)}, {"value", target_}});
    context.note("Sa", sa);
    context.note("h_rms", h_rms);
    context.note("h_prime_rms", h_prime);
  }

 private:
  bem::RoughSurfaceSpec spec_;
  bem::RoughnessMeasure measure_ = bem::RoughnessMeasure::HPrimeRms;
  double target_ = 0.0;
  std::string file_;
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(SurfaceGenerate)
