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
#include <cmath>

#include <fmt/format.h>

#include "surface_sides.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/io/topography_io.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies {

namespace {

class SurfaceGenerate final : public Study {
 public:
  std::string name() const override { return "surface/generate"; }
  std::string summary() const override {
    return "Generate a periodic rough surface with the PSD of thesis Fig. 1.3 (plateau k_l…k_r, slope −2(H+1) from "
           "k_r to k_s) and write it to HDF5 + XDMF";
  }
  std::string default_case_name() const override { return "surface"; }
  Schema schema() const override {
    const std::string k = "surface.generate.";
    return {
        {k + "n", "integer", "4 … 65536", "1", "", "points per side of a square grid", "--n"},
        {k + "nx", "integer", "4 … 65536", "1", "n", "points along x", "--nx"},
        {k + "ny", "integer", "4 … 65536", "1", "n", "points along y", "--ny"},
        {k + "size", "number", "> 0", "m", "", "side L of the square surface (\"100 um\" also works), or Lx,Ly",
         "--size"},
        {k + "hurst", "number", "(0, 1]", "1", "", "Hurst exponent H", "--hurst"},
        {k + "k_l", "number", "(0, k_r]", "1", "", "wavenumber of the longest wavelength, q_l = 2π k_l / L", "--kl"},
        {k + "k_r", "number", "[k_l, k_s]", "1", "k_l", "roll-off wavenumber (k_l: no plateau)", "--kr"},
        {k + "k_s", "number", "[k_r, min(nx, ny)/2]", "1", "", "wavenumber of the shortest wavelength", "--ks"},
        {k + "seed", "integer", "≥ 0", "1", "0", "seed of the random phases (same seed, same surface)", "--seed"},
        {k + "hprime_rms", "number", "(0, 100]", "1", "", "rescale to this RMS slope h'_RMS (1.6); one of three",
         "--hprime-rms"},
        {k + "h_rms", "number", "(0, side]", "m", "", "rescale to this RMS height h_RMS (1.5)", "--h-rms"},
        {k + "sa", "number", "(0, side]", "m", "", "rescale to this arithmetic mean deviation Sa (1.4)", "--sa"},
        {k + "file", "string", "a file name ending in .h5", "", "surface.h5",
         "the surface's name in the output folder (an .xdmf sidecar beside it)", "--file"},
    };
  }

  std::vector<std::string> prepare(Config& cfg) override {
    const Config c = cfg.section("surface.generate");
    const Range points = Range::closed(4, 65536);
    for (const char* key : {"n", "nx", "ny"}) c.mark_used(key);
    const long n = c.has("n") ? c.integer("n", points) : 0;
    const long nx = c.has("nx") ? c.integer("nx", points) : n;  // --nx, --ny override --n
    const long ny = c.has("ny") ? c.integer("ny", points) : n;
    if (nx == 0 || ny == 0)
      throw c.error("n", "the grid is not given", "n (square; --n) or nx and ny (--nx, --ny)");
    const auto size = read_sides(c, "size");
    if (!size.lx) throw c.error("size", "the side of the surface is not given", "a positive length (--size)");
    const double lx = *size.lx, ly = size.ly.value_or(lx);
    spec_.grid = Grid2D(static_cast<std::size_t>(nx), static_cast<std::size_t>(ny), lx, ly);
    spec_.hurst = c.number("hurst");
    spec_.k_l = c.number("k_l");
    spec_.k_r = c.number_or("k_r", spec_.k_l);
    spec_.k_s = c.number("k_s");
    spec_.seed = static_cast<std::uint64_t>(c.integer_or("seed", 0, Range::non_negative()));
    // The library checks H and 0 < k_l ≤ k_r ≤ k_s ≤ Nyquist; its message is named after the key that was given.
    try {
      bem::validate(spec_);
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
    // Bounds that keep every derived figure finite and the surface a surface: an RMS slope up to 100 (the
    // BEM assumes small slopes: ≲ 1), heights up to the side of the surface; and the slope an h_RMS or Sa
    // target gives on this spectrum within the same bound (bem::check_roughness_target, as contact.rough's).
    const double side = std::min(lx, ly);
    const char* key = c.has("hprime_rms") ? "hprime_rms" : c.has("h_rms") ? "h_rms" : "sa";
    if (c.has("hprime_rms")) {
      measure_ = bem::RoughnessMeasure::HPrimeRms;
      target_ = c.number("hprime_rms", Range::open_closed(0.0, bem::max_hprime_rms));
    } else if (c.has("h_rms")) {
      measure_ = bem::RoughnessMeasure::HRms;
      target_ = c.number("h_rms", Range::open_closed(0.0, side), units::length);
    } else {
      measure_ = bem::RoughnessMeasure::Sa;
      target_ = c.number("sa", Range::open_closed(0.0, side), units::length);
    }
    if (const auto p = bem::roughness_target_problem(spec_, measure_, target_); !p.problem.empty())
      throw c.error(key, p.problem, p.allowed);
    file_ = output_file_name(c, "file", "surface.h5", {".h5"});
    // The surface, its spectrum and the copy written out, before any is allocated.
    require_memory(48.0 * static_cast<double>(nx) * static_cast<double>(ny),
                   fmt::format("surface generate: a {} × {} surface", nx, ny), "give a smaller --n (or --nx, --ny)");
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
