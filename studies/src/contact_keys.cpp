// The key table of [contact] (contact_case.hpp): every key declared once, in
// the order a case's refusals come (the surface, the boundary, the modulus,
// the law, the loads, the solver), with the checks between keys as steps. The friction key decides which keys are read and which struct
// (NormalCase or FrictionalCase) the shared ones fill.
#include <algorithm>
#include <fmt/format.h>

#include "contact_case.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/units.hpp"

namespace wearscale::studies {

// Named, so that nothing here meets a name of the studies' other files (one unity translation unit).
namespace contact_table {

using namespace bem;
using K = ContactCase;

static_assert(ContactOptions::max_tolerance == FrictionalOptions::max_tolerance,
              "contact.tolerance has one range for both solvers");

bool frictional(const K& k) { return k.given.friction != "none"; }
// Whether the case gives `key` of [contact].
auto gives(const char* key) {
  return [key](const Config& c, const K&) { return c.has(key); };
}
// A member of the rough surface's spec, made when first asked for (the schema's fresh case has none).
template <class T>
auto rough(T RoughSurfaceSpec::*member) {
  return [member](K& k) -> T& {
    if (!k.rough) k.rough.emplace();
    return k.rough->spec.*member;
  };
}
// The highest wavenumber of the grid, n/2.
double nyquist(const K& k) { return static_cast<double>(std::min(k.grid.nx, k.grid.ny) / 2); }

// The grid: the file's (read now, with dataset, missing and size), or grid × size.
void set_grid(const Config& c, K& k) {
  if (!k.given.surface.empty()) {  // under mpirun every rank reads the file alike (a refusal is every rank's)
    TopographyOptions read = k.given.read;
    if (k.given.size) read.size.lx = read.size.ly = *k.given.size;
    k.measured = read_measured_topography(k.given.surface, read).heights;
    k.grid = k.measured.grid();
    if (k.grid.nx < static_cast<std::size_t>(k.ranks))
      throw c.error("surface",
                    fmt::format("'{}' has {} rows, fewer than the {} ranks that would each hold a slab of them",
                                k.given.surface.string(), k.grid.nx, k.ranks),
                    fmt::format("a surface of at least {} rows, or fewer ranks", k.ranks));
  } else {
    k.grid = Grid2D::square(static_cast<std::size_t>(k.given.grid), k.given.size.value_or(0.0));
  }
  if (c.has("rough")) rough(&RoughSurfaceSpec::grid)(k) = k.grid;
}

// [contact.rough]'s one target, held to the bounds of every generated surface (as `surface generate`'s).
void set_roughness_target(const Config& c, K& k) {
  if (!k.rough) return;
  const ContactInputs& g = k.given;
  const char* key = g.hprime_rms ? "rough.hprime_rms" : g.h_rms ? "rough.h_rms" : "rough.sa";
  k.rough->measure = g.hprime_rms ? RoughnessMeasure::HPrimeRms : g.h_rms ? RoughnessMeasure::HRms : RoughnessMeasure::Sa;
  k.rough->target = g.hprime_rms ? *g.hprime_rms : g.h_rms ? *g.h_rms : g.sa.value_or(0.0);
  if (const auto p = roughness_target_problem(k.rough->spec, k.rough->measure, k.rough->target); !p.problem.empty())
    throw c.error(key, p.problem, p.allowed);
}

// The loads a case may give: frictionless one of three, frictional one normal and at most one tangential.
void check_loads(const Config& c, const K& k) {
  const int normal = int(c.has("mean_pressure")) + int(c.has("normal_load"));
  if (!frictional(k)) {
    if (normal + int(c.has("interference")) != 1)
      throw c.error("mean_pressure", "give exactly one of mean_pressure, normal_load, interference", "one load");
    return;
  }
  if (c.has("interference"))
    throw c.error("interference", "frictional contact imposes the mean tractions", "mean_pressure or normal_load");
  if (normal != 1) throw c.error("mean_pressure", "give exactly one of mean_pressure, normal_load", "one normal load");
  if (c.has("tangential_pressure") && c.has("tangential_load"))
    throw c.error("tangential_pressure", "give at most one of tangential_pressure, tangential_load",
                  "one tangential load");
}

void set_loads(const Config& c, K& k) {
  const ContactInputs& g = k.given;
  const double p0 = g.normal_load ? *g.normal_load / k.grid.area() : g.mean_pressure.value_or(0.0);
  if (k.friction) {
    k.friction->load.normal = p0;
    k.friction->tangential_key = c.has("tangential_load") ? "tangential_load" : "tangential_pressure";
    k.friction->load.x = g.tangential_load ? *g.tangential_load / k.grid.area() : g.tangential_pressure;
    return;
  }
  k.normal.p0 = p0;
  k.normal.imposes_interference = g.interference.has_value();
  k.normal.delta = g.interference.value_or(0.0);
}

}  // namespace contact_table

const KeyTable<ContactCase>& contact_keys() {
  using namespace contact_table;
  // A member of the solver the friction key chose.
  const auto solver = [](auto normal, auto frictional_) {
    return [normal, frictional_](K& k) -> auto& { return k.friction ? k.friction.value().*frictional_ : k.normal.*normal; };
  };
  const auto options = [](auto normal, auto frictional_) {
    return [normal, frictional_](K& k) -> auto& {
      return k.friction ? k.friction->options.*frictional_ : k.normal.options.*normal;
    };
  };
  const auto normal_only = [](const Config&, const K& k) { return !frictional(k); };
  const auto frictional_only = [](const Config&, const K& k) { return frictional(k); };
  const auto no_surface = [](const Config& c, const K&) { return !c.has("surface"); };
  const auto has_rough = gives("rough");
  const Range side = Range::positive();
  const auto connectivity = std::vector<std::pair<std::string, Connectivity>>{{"four", Connectivity::Four},
                                                                               {"eight", Connectivity::Eight}};
  static const auto table =
      KeyTable<K>()
          .choice("friction", [](K& k) -> std::string& { return k.given.friction; },
                  std::vector<std::string>{"none", "coulomb", "tresca"}, "friction law (Appendix A)")
          .flag("--friction")
          .then([](const Config&, K& k) {
            if (frictional(k)) k.friction.emplace();
          })
          // ---- The surface: a file, a rough surface and/or a sphere ----
          .custom("surface", "path", "", "", "height file of the rigid surface: " + supported_topography_formats(),
                  [](const Config& c, const std::string& key, K& k) {
                    if (c.has(key)) k.given.surface = c.path(key);
                  })
          .flag("--surface")
          .string("dataset", [](K& k) -> std::string& { return k.given.read.dataset; }, "dataset of an HDF5 height file")
          .read_if(gives("surface"))
          .integer("grid", [](K& k) -> long& { return k.given.grid; }, Range::closed(8, 16384),
                   "points per side of a generated surface")
          .required()
          .read_if(no_surface)
          // Required for a generated surface; a file's own when absent (no default stands in).
          .custom("size", "number", side.describe(), units::length.to_string(),
                  "side of the periodic cell (a file's: overrides its own)",
                  [side](const Config& c, const std::string& key, K& k) {
                    if (c.has(key) || k.given.surface.empty()) k.given.size = c.number(key, side, units::length);
                  })
          .fallback("the file's")
          .choice("missing", [](K& k) -> MissingPoints& { return k.given.read.missing; },
                  std::vector<std::pair<std::string, MissingPoints>>{{"refuse", MissingPoints::Refuse},
                                                                     {"fill", MissingPoints::Fill}},
                  MissingPointsChoice::doc)
          .read_if(gives("surface"))
          .flag("--missing")
          .then(set_grid)
          .number("rough.hurst", rough(&RoughSurfaceSpec::hurst), Range::open_closed(0.0, 1.0),
                  "Hurst exponent H of a generated rough surface")
          .required()
          .read_if(has_rough)
          .number("rough.k_l", rough(&RoughSurfaceSpec::k_l), Range::positive(), "roll-off wavenumber (in 1/L)")
          .required()
          .range_from([](const K& k) { return Range::open_closed(0.0, nyquist(k)); }, "(0, n/2]")
          .read_if(has_rough)
          .number("rough.k_r", rough(&RoughSurfaceSpec::k_r), Range::positive(), "start of the self-affine range")
          .range_from([](const K& k) { return Range::closed(k.rough->spec.k_l, nyquist(k)); }, "[k_l, n/2]")
          .computed_default([](const K& k) { return k.rough->spec.k_l; }, "k_l")
          .read_if(has_rough)
          .number("rough.k_s", rough(&RoughSurfaceSpec::k_s), Range::positive(), "cut-off wavenumber")
          .required()
          .range_from([](const K& k) { return Range::closed(k.rough->spec.k_r, nyquist(k)); }, "[k_r, n/2]")
          .read_if(has_rough)
          .integer("rough.seed", rough(&RoughSurfaceSpec::seed), Range::non_negative(), "random seed")
          .read_if(has_rough)
          .then([](const Config& c, K& k) {
            if (!k.rough) return;
            const int targets = int(c.has("rough.hprime_rms")) + int(c.has("rough.h_rms")) + int(c.has("rough.sa"));
            if (targets != 1)
              throw c.error("rough.hprime_rms", "give exactly one of hprime_rms, h_rms, sa", "one roughness target");
          })
          .optional_number("rough.hprime_rms", [](K& k) -> std::optional<double>& { return k.given.hprime_rms; },
                           Range::positive(), units::dimensionless, "RMS slope h' (one of hprime_rms, h_rms, sa)")
          .read_if(has_rough)
          .optional_number("rough.h_rms", [](K& k) -> std::optional<double>& { return k.given.h_rms; },
                           Range::positive(), units::length, "RMS height")
          .read_if(has_rough)
          .optional_number("rough.sa", [](K& k) -> std::optional<double>& { return k.given.sa; }, Range::positive(),
                           units::length, "arithmetic mean height Sa")
          .read_if(has_rough)
          .then(set_roughness_target)
          .number("sphere.radius", &K::sphere_radius, Range::positive(), units::length,
                  "radius of a sphere added at the cell's centre")
          .required()
          .read_if(gives("sphere"))
          .then([](const Config& c, K&) {
            if (!c.has("surface") && !c.has("rough") && !c.has("sphere"))
              throw c.error("surface", "no surface: give surface = FILE, a [contact.rough] or a [contact.sphere] table",
                            "a file, rough and/or sphere");
          })
          // ---- The elastic flat ----
          .then([](const Config& c, K& k) {
            if (frictional(k) && !c.has("poisson"))
              throw c.error("poisson",
                            "frictional contact needs Poisson's ratio: normal and tangential couple through it (4.22)",
                            "−1 < ν ≤ 0.5 (0.5: decoupled)");
          })
          .choice("boundary", [](K& k) -> Boundary& { return k.normal.boundary; },
                  std::vector<std::pair<std::string, Boundary>>{{"periodic", Boundary::Periodic},
                                                                {"free", Boundary::Free}},
                  "periodic cell, or a window on an isolated body (frictionless only)")
          .then([](const Config& c, K& k) {
            if (!frictional(k)) return;
            if (k.normal.boundary == Boundary::Free)
              throw c.error("boundary",
                            "a free boundary is implemented for frictionless contact only (friction = \"none\")",
                            "\"periodic\" with friction");
            if (int(c.has("young")) + int(c.has("e_star")) != 1)
              throw c.error("young", "give exactly one of young, e_star", "one elastic modulus");
          })
          .optional_number("e_star", [](K& k) -> std::optional<double>& { return k.given.e_star; }, Range::positive(),
                           units::pressure, "contact modulus E* (1.12)")
          .flag("--e-star")
          .number("young", [](K& k) -> double& { return k.given.young; }, Range::positive(), units::pressure,
                  "Young's modulus of the elastic flat")
          .required()
          .read_if([](const Config& c, const K&) { return !c.has("e_star"); })
          .number("poisson", [](K& k) -> double& { return k.given.poisson; }, Range::open_closed(-1.0, 0.5),
                  "Poisson's ratio ν of the elastic flat")
          .required()
          .read_if([](const Config& c, const K& k) { return frictional(k) || !c.has("e_star"); })
          .flag("--poisson")
          .then([](const Config&, K& k) {
            const ContactInputs& g = k.given;
            const double nu = g.poisson;
            if (k.friction) {
              k.friction->poisson = nu;
              k.friction->young = g.e_star ? *g.e_star * (1.0 - nu * nu) : g.young;
            } else {
              k.normal.e_star = g.e_star ? *g.e_star : g.young / (1.0 - nu * nu);  // rigid on an elastic flat (1.12)
            }
          })
          // ---- The friction law (Appendix A) ----
          .number("friction_coefficient", [](K& k) -> double& { return k.given.friction_coefficient; },
                  Range::non_negative(), "Coulomb friction coefficient μ (A.2)")
          .required()
          .read_if([](const Config&, const K& k) { return k.given.friction == "coulomb"; })
          .flag("--mu")
          .number("shear_strength", [](K& k) -> double& { return k.given.shear_strength; }, Range::non_negative(),
                  units::pressure, "Tresca shear strength σ_m,T (A.3)")
          .required()
          .read_if([](const Config&, const K& k) { return k.given.friction == "tresca"; })
          .flag("--shear-strength")
          .then([](const Config&, K& k) {
            if (!k.friction) return;
            k.friction->law = k.given.friction == "coulomb" ? FrictionLaw::coulomb(k.given.friction_coefficient)
                                                            : FrictionLaw::tresca(k.given.shear_strength);
          })
          // ---- The loads ----
          .then(check_loads)
          .optional_number("mean_pressure", [](K& k) -> std::optional<double>& { return k.given.mean_pressure; },
                           Range::non_negative(), units::pressure, "imposed mean pressure")
          .flag("--pressure")
          .optional_number("normal_load", [](K& k) -> std::optional<double>& { return k.given.normal_load; },
                           Range::non_negative(), units::force, "imposed normal force on the cell")
          .flag("--load")
          .optional_number("interference", [](K& k) -> std::optional<double>& { return k.given.interference; },
                           Range::any(), units::length, "imposed interference (frictionless)")
          .read_if(normal_only)
          .flag("--interference")
          .number("tangential_pressure", [](K& k) -> double& { return k.given.tangential_pressure; }, Range::any(),
                  units::pressure, "imposed mean tangential traction along x")
          .read_if([](const Config& c, const K& k) { return frictional(k) && !c.has("tangential_load"); })
          .flag("--tangential-pressure")
          .optional_number("tangential_load", [](K& k) -> std::optional<double>& { return k.given.tangential_load; },
                           Range::any(), units::force, "imposed tangential force on the cell along x")
          .read_if(frictional_only)
          .then(set_loads)
          // ---- The solver ----
          .number("tolerance", options(&ContactOptions::tolerance, &FrictionalOptions::tolerance),
                  Range::open_closed(0.0, ContactOptions::max_tolerance), "relative convergence tolerance")
          .fallback(fmt::format("{} (frictional {})", key_table_detail::default_text(ContactOptions{}.tolerance),
                                key_table_detail::default_text(FrictionalOptions{}.tolerance)))
          .integer("max_iterations", options(&ContactOptions::max_iterations, &FrictionalOptions::max_iterations),
                   Range::at_least(1), "iteration limit")
          .fallback(fmt::format("{} (frictional {})", ContactOptions{}.max_iterations,
                                FrictionalOptions{}.max_iterations))
          .choice("preconditioner", [](K& k) -> ContactMethod& { return k.normal.options.method; },
                  std::vector<std::pair<std::string, ContactMethod>>{{"two-level", ContactMethod::TwoLevelCG},
                                                                     {"full", ContactMethod::PreconditionedCG}},
                  "normal solve's preconditioner: two-level (S on a 2× coarser grid: the same iterations at a "
                  "quarter of the transforms; a free window or an odd grid uses full), or full (the stiffness S by "
                  "an FFT pair)")
          .read_if(normal_only)
          .choice("connectivity", solver(&NormalCase::connectivity, &FrictionalCase::connectivity), connectivity,
                  "neighbours joining a micro-contact")
          // ---- What a frictional contact adds ----
          .optional_number("tensile_strength",
                           [](K& k) -> std::optional<double>& { return k.given.tensile_strength; }, Range::positive(),
                           units::pressure, "tensile strength σ_m: crack initiation (4.25) per micro-contact")
          .read_if(frictional_only)
          .flag("--tensile-strength")
          .custom("stress_depths", "list", Range::non_negative().describe(), units::length.to_string(),
                  "depths of the subsurface stress fields",
                  [](const Config& c, const std::string& key, K& k) {
                    if (c.has(key)) k.friction->depths = c.numbers(key, Range::non_negative(), units::length);
                  })
          .read_if(frictional_only)
          .then([](const Config&, K& k) {
            // SIGINT/SIGTERM end a long solve within an iteration.
            if (k.friction) {
              k.friction->crack = k.given.tensile_strength.has_value();
              k.friction->sigma_m = k.given.tensile_strength.value_or(0.0);
              k.friction->options.stop = [] { return interrupt_requested(); };
            } else {
              k.normal.options.stop = [] { return interrupt_requested(); };
            }
          });
  return table;
}

}  // namespace wearscale::studies
