// The contact study ([contact]): a rigid surface (a file, a generated rough
// surface and/or a sphere) on an elastic flat, frictionless (Polonsky–Keer)
// or frictional (Appendix A); fields in contact.h5 (+ .xdmf), micro-contacts
// in clusters.csv, headline figures to the runner.
//
//   [contact]
//   surface = "rough.h5"        # or [contact.rough] / [contact.sphere] on grid × size
//   e_star = "37.6 GPa"         # or young + poisson (rigid surface on an elastic flat)
//   mean_pressure = "1 MPa"     # or normal_load (per cell) or interference
//   boundary = "periodic"       # or "free": the grid is a window on an isolated body
//                               # (zero-padded half-space; frictionless only)
//
// Frictional contact (Appendix A) adds, with poisson given (and young or e_star):
//   friction = "coulomb"        # "none" (default) | "coulomb" | "tresca"
//   friction_coefficient = 0.5  # μ (A.2), Coulomb
//   shear_strength = "250 MPa"  # σ_m,T (A.3), Tresca
//   tangential_pressure = "2 MPa"   # mean p_x (or tangential_load, a force on the cell)
//   tensile_strength = "500 MPa"    # optional σ_m: crack initiation (4.25) per micro-contact
//   stress_depths = ["1 um", "5 um"]  # optional: σ_I and τ_m fields below the surface
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "contact_case.hpp"
#include "contact_slab.hpp"
#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/crack_initiation.hpp"
#include "wearscale/bem/frictional_contact.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/principal_stresses.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/subsurface_stress.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/topography_io.hpp"
#include "wearscale/io/xdmf.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies {

namespace {

using namespace bem;

// Memory per grid point of a study, measured (peak RSS at 1024², with the
// outputs): normal contact about 120 B, frictional with stresses about 580 B.
double bytes_per_point(const std::string& friction) { return friction == "none" ? 160.0 : 640.0; }

RealField build_surface(const Config& c, const std::string& friction) {
  RealField h;
  if (c.has("surface")) {
    TopographyOptions read;
    read.dataset = c.string_or("dataset", default_surface_dataset);
    if (c.has("size")) read.size.lx = read.size.ly = c.number("size", Range::positive(), units::length);
    read.missing = missing_points_from(
        c.choice_or(MissingPointsChoice::key, MissingPointsChoice::fallback, {"refuse", "fill"}),
        c.full_key(MissingPointsChoice::key));
    h = read_measured_topography(c.path("surface"), read).heights;
  } else {
    const long n = c.integer("grid", Range::closed(8, 16384));
    require_memory(bytes_per_point(friction) * static_cast<double>(n) * static_cast<double>(n),
                   fmt::format("{}: key '{}' = {}: a contact study of {} × {} points", c.where("grid"),
                               c.full_key("grid"), n, n, n),
                   "give a smaller grid");
    const double l = c.number("size", Range::positive(), units::length);
    h = RealField(Grid2D::square(static_cast<std::size_t>(n), l));
  }
  const Grid2D g = h.grid();
  if (c.has("rough")) {
    const RoughCase r = read_rough_case(c.section("rough"), g);
    h = add(h, generate_surface(r.spec, r.measure, r.target));
  }
  if (c.has("sphere")) {
    const double radius = c.number("sphere.radius", Range::positive(), units::length);
    h = add(h, sphere(g, radius, 0.5 * g.lx, 0.5 * g.ly));
  }
  if (!c.has("surface") && !c.has("rough") && !c.has("sphere"))
    throw c.error("surface", "no surface: give surface = FILE, a [contact.rough] or a [contact.sphere] table",
                  "a file, rough and/or sphere");
  return h;
}

// Frictionless normal contact (Polonsky–Keer).
void run_normal_study(const Config& config, const Config& c, const RealField& h, RunContext& context) {
  const Grid2D g = h.grid();
  const NormalCase n = read_normal_case(c, g);
  config.reject_unknown_keys();  // every check before any work

  log::info("contact: {} , E* = {:g} Pa, {} boundary", g.to_string(), n.e_star, to_string(n.boundary));
  NormalContact contact(h, n.e_star, n.boundary);
  const ContactResult r = n.solve(contact);
  write_normal_study(config, n, h, contact.pressure(), contact.gap(), contact.displacement(), r, context);
}

// Frictional contact (Appendix A): tractions, stick/slip map, displacements,
// surface (and subsurface) stresses, and the criterion (4.25) if σ_m is given.
void run_frictional_study(const Config& config, const Config& c, const RealField& h, const std::string& law_name,
                          RunContext& context) {
  const auto& out = context.output_dir();
  const Grid2D g = h.grid();
  if (!c.has("poisson"))
    throw c.error("poisson", "frictional contact needs Poisson's ratio: normal and tangential couple through it (4.22)",
                  "−1 < ν ≤ 0.5 (0.5: decoupled)");
  const double nu = c.number("poisson", Range::open_closed(-1.0, 0.5));
  if (contact_boundary(c) == Boundary::Free)
    throw c.error("boundary", "a free boundary is implemented for frictionless contact only (friction = \"none\")",
                  "\"periodic\" with friction");
  if (int(c.has("young")) + int(c.has("e_star")) != 1)
    throw c.error("young", "give exactly one of young, e_star", "one elastic modulus");
  const double young = c.has("young") ? c.number("young", Range::positive(), units::pressure)
                                      : c.number("e_star", Range::positive(), units::pressure) * (1.0 - nu * nu);
  const FrictionLaw law =
      law_name == "coulomb" ? FrictionLaw::coulomb(c.number("friction_coefficient", Range::non_negative()))
                            : FrictionLaw::tresca(c.number("shear_strength", Range::non_negative(), units::pressure));
  if (c.has("interference"))
    throw c.error("interference", "frictional contact imposes the mean tractions", "mean_pressure or normal_load");
  if (int(c.has("mean_pressure")) + int(c.has("normal_load")) != 1)
    throw c.error("mean_pressure", "give exactly one of mean_pressure, normal_load", "one normal load");
  if (c.has("tangential_pressure") && c.has("tangential_load"))
    throw c.error("tangential_pressure", "give at most one of tangential_pressure, tangential_load",
                  "one tangential load");
  MeanTraction load;
  load.normal = c.has("mean_pressure") ? c.number("mean_pressure", Range::non_negative(), units::pressure)
                                       : c.number("normal_load", Range::non_negative(), units::force) / g.area();
  const std::string tangential_key = c.has("tangential_load") ? "tangential_load" : "tangential_pressure";
  load.x = c.has("tangential_load") ? c.number("tangential_load", Range::any(), units::force) / g.area()
                                    : c.number_or("tangential_pressure", 0.0, Range::any(), units::pressure);
  FrictionalOptions options;
  options.tolerance = c.number_or("tolerance", 1e-10, Range::open(0.0, 1.0));
  options.max_iterations = static_cast<int>(c.integer_or("max_iterations", 20000, Range::at_least(1)));
  const auto connectivity =
      c.choice_or("connectivity", "four", {"four", "eight"}) == "eight" ? Connectivity::Eight : Connectivity::Four;
  const bool crack = c.has("tensile_strength");
  const double sigma_m = crack ? c.number("tensile_strength", Range::positive(), units::pressure) : 0.0;
  const std::vector<double> depths =
      c.has("stress_depths") ? c.numbers("stress_depths", Range::non_negative(), units::length) : std::vector<double>{};
  config.reject_unknown_keys();  // every check before any work

  log::info("contact: {} , E = {:g} Pa, ν = {:g}, {} friction", g.to_string(), young, nu, law.to_string());
  FrictionalContact contact(h, young, nu, law);
  FrictionalResult r;
  try {
    r = contact.solve(load, options);
  } catch (const InputError& e) {  // gross sliding: name the key that asked for it
    throw c.error(tangential_key, e.what());
  }
  if (r.unsettled_points > 0)
    log::warn("contact: {} contact-edge points keep a friction limit that differs from the law's (the limit "
              "cycled between iterations; see frictional_contact.hpp)",
              r.unsettled_points);
  const ContactMap map = find_clusters(contact.traction().z, connectivity);

  SubsurfaceStress solid(g, nu);
  solid.set_traction(contact.traction());
  StressField stress(g);
  PrincipalStresses surface(g), deep(g);
  solid.stress(0.0, stress);
  principal_stresses(stress, surface);

  RealField in_contact(g);
  for (std::size_t k = 0; k < g.size(); ++k) in_contact[k] = contact.traction().z[k] > 0.0 ? 1.0 : 0.0;
  const auto h5_path = out / "contact.h5";
  H5Writer h5(h5_path);
  std::vector<XdmfField> xdmf;
  auto field = [&](const std::string& path, const RealField& f, const char* unit, const std::string& name) {
    h5.write_field(path, f, unit);
    xdmf.push_back({path, name});
  };
  field("/surface/height", h, "m", "height");
  field("/fields/pressure", contact.traction().z, "Pa", "p_N");
  field("/fields/traction_x", contact.traction().x, "Pa", "p_x");
  field("/fields/traction_y", contact.traction().y, "Pa", "p_y");
  field("/fields/stick_slip", contact.stick_slip_map(), "1", "stick_slip");
  h5.set_attribute("/fields/stick_slip", "values", "0 open, 1 stick, 2 slip");
  field("/fields/gap", contact.normal_gap(), "m", "gap");
  field("/fields/slip_x", contact.slip().x, "m", "slip_x");
  field("/fields/slip_y", contact.slip().y, "m", "slip_y");
  field("/fields/displacement", contact.displacement().z, "m", "u_z");
  field("/fields/displacement_x", contact.displacement().x, "m", "u_x");
  field("/fields/displacement_y", contact.displacement().y, "m", "u_y");
  field("/fields/contact", in_contact, "1", "contact");
  field("/stress/surface/sigma_I", surface.first, "Pa", "sigma_I");
  field("/stress/surface/sigma_III", surface.third, "Pa", "sigma_III");
  field("/stress/surface/tau_max", surface.max_shear, "Pa", "tau_max");
  double deep_tau = 0.0, deep_tau_depth = 0.0;
  for (std::size_t d = 0; d < depths.size(); ++d) {
    solid.stress(depths[d], stress);
    principal_stresses(stress, deep);
    const std::string group = fmt::format("/stress/depth_{}", d);
    field(group + "/sigma_I", deep.first, "Pa", fmt::format("sigma_I_depth_{}", d));
    field(group + "/tau_max", deep.max_shear, "Pa", fmt::format("tau_max_depth_{}", d));
    h5.set_attribute(group, "depth", depths[d]);
    const double m = *std::max_element(deep.max_shear.begin(), deep.max_shear.end());
    if (m > deep_tau) {
      deep_tau = m;
      deep_tau_depth = depths[d];
    }
  }
  h5.set_attribute("/", "case_toml", config.to_toml());

  auto report = [&](const std::string& name, double v, const std::string& unit, const std::string& what) {
    context.report(name, v, unit, what);
    h5.write_scalar("/results/" + name, v, unit);
  };
  report("mean_pressure", r.mean_traction.normal, "Pa", "mean normal traction ⟨p_N⟩");
  report("mean_tangential_pressure", r.mean_traction.x, "Pa", "mean tangential traction ⟨p_x⟩");
  report("friction_ratio", r.frictional_force_ratio, "1", "‖⟨p_T⟩‖/⟨p_N⟩");
  report("contact_fraction", r.contact_fraction, "1", "real contact area ratio A/A0");
  report("stick_fraction", r.stick_fraction, "1", "sticking area / A0");
  report("slip_fraction", r.slip_fraction, "1", "sliding area / A0");
  report("full_sliding", r.full_sliding ? 1.0 : 0.0, "1", "1 if every contact point slides");
  if (!r.full_sliding)
    report("tangential_displacement", r.tangential_displacement_x, "m", "δ_x, rigid displacement of the stick zone");
  report("interference", r.interference, "m", "summit depth below the mean deformed surface");
  report("elastic_energy", r.elastic_energy, "J", "elastic energy ½∫p·u dA (4.1)");
  report("clusters", static_cast<double>(map.clusters.size()), "1", "number of micro-contacts");
  report("iterations", r.iterations, "1", "iterations of Algorithm 1");
  report("bound_updates", r.bound_updates, "1", "updates of the lagged friction limit");
  report("unsettled_points", static_cast<double>(r.unsettled_points), "1",
         "contact points whose friction limit differs from the law's");
  report("error", r.error, "1", "cost (A.14) relative to Σp·h_rms");
  report("max_sigma_I", *std::max_element(surface.first.begin(), surface.first.end()), "Pa",
         "largest first principal stress on the surface (4.24)");
  if (!depths.empty())
    report("max_tau_subsurface", deep_tau, "Pa",
           fmt::format("largest τ_m = (σ_I − σ_III)/2 over the requested depths (at {:g} m)", deep_tau_depth));

  // Micro-contacts, with (4.25) at their edges if σ_m is given.
  std::vector<double> area, cx, cy, trailing, leading, initiates;
  std::vector<EdgeCrackCheck> checks;
  if (crack && !map.clusters.empty()) {
    const double dir = load.x != 0.0 ? load.x : 1.0;  // along +x when there is no tangential load
    checks = crack_initiation(map, surface, dir, 0.0, sigma_m);
  }
  double count = 0.0;
  for (std::size_t i = 0; i < map.clusters.size(); ++i) {
    area.push_back(map.clusters[i].area);
    cx.push_back(map.clusters[i].centroid_x);
    cy.push_back(map.clusters[i].centroid_y);
    if (crack) {
      trailing.push_back(checks[i].trailing_tension);
      leading.push_back(checks[i].leading_compression);
      initiates.push_back(checks[i].initiates() ? 1.0 : 0.0);
      count += initiates.back();
    }
  }
  std::vector<std::string> names = {"area", "centroid_x", "centroid_y"};
  std::vector<std::string> table_units = {"m^2", "m", "m"};
  std::vector<std::span<const double>> columns = {area, cx, cy};
  if (crack) {
    report("crack_initiation_sites", count, "1", "micro-contacts meeting (4.25) at both edges");
    names.insert(names.end(), {"trailing_sigma_I", "leading_sigma_III", "crack_initiation"});
    table_units.insert(table_units.end(), {"Pa", "Pa", "1"});
    columns.insert(columns.end(), {trailing, leading, initiates});
  }
  h5.write_table("/clusters", names, columns, table_units);
  XdmfSidecar sidecar(g);
  sidecar.add(h5, xdmf);
  h5.commit();
  sidecar.write(out / "contact.xdmf", h5_path);
  std::vector<std::string> comments = {"micro-contacts of the solved contact, largest first"};
  if (crack)
    comments.push_back(fmt::format("crack initiation (4.25) at σ_m = {:g} Pa, from the surface stresses", sigma_m));
  write_csv(out / "clusters.csv", names, columns, table_units, comments);
  for (const auto& f : {h5_path, out / "contact.xdmf", out / "clusters.csv"}) context.add_file(f);
}

class ContactStudy final : public Study {
 public:
  std::string name() const override { return "contact"; }
  std::string summary() const override {
    return "normal or frictional contact of a rigid surface (file, rough, sphere) on an elastic flat (BEM)";
  }
  Schema schema() const override;
  // Under mpirun (P > 1) the case is read and checked on every rank before any
  // work (contact_slab.hpp says what is refused); serial runs read it in run().
  std::vector<std::string> prepare(Config& config) override {
    if (mpi::size() > 1) slab_ = read_slab_case(config);
    return {};
  }
  bool distributed() const override { return true; }
  void run_other_rank(const Config& config) override { run_slab_contact(config, slab_.value(), nullptr); }
  void run(const Config& config, RunContext& context) override {
    if (slab_) return run_slab_contact(config, *slab_, &context);
    const Config c = config.section("contact");
    const std::string friction = c.choice_or("friction", "none", {"none", "coulomb", "tresca"});
    const RealField h = build_surface(c, friction);
    require_memory(bytes_per_point(friction) * static_cast<double>(h.grid().size()),
                   fmt::format("a {} contact study of {} × {} points", friction == "none" ? "normal" : "frictional",
                               h.grid().nx, h.grid().ny));
    if (friction == "none")
      run_normal_study(config, c, h, context);
    else
      run_frictional_study(config, c, h, friction, context);
  }

 private:
  std::optional<SlabCase> slab_;  // read by prepare() under mpirun
};

Schema ContactStudy::schema() const {
  return {
      {"contact.surface", "path", "", "", "", "height file of the rigid surface: " + bem::supported_topography_formats(),
       "--surface"},
      {"contact.dataset", "string", "", "", std::string(default_surface_dataset), "dataset of an HDF5 height file", ""},
      {"contact.missing", "choice", "refuse | fill", "", MissingPointsChoice::fallback, MissingPointsChoice::doc,
       "--missing"},
      {"contact.grid", "integer", "8 … 16384", "1", "", "points per side of a generated surface", ""},
      {"contact.size", "number", "> 0", "m", "", "side of the periodic cell", ""},
      {"contact.rough.hurst", "number", "(0, 1]", "1", "", "Hurst exponent H of a generated rough surface", ""},
      {"contact.rough.k_l", "number", "(0, n/2]", "1", "", "roll-off wavenumber (in 1/L)", ""},
      {"contact.rough.k_r", "number", "[k_l, n/2]", "1", "k_l", "start of the self-affine range", ""},
      {"contact.rough.k_s", "number", "[k_r, n/2]", "1", "", "cut-off wavenumber", ""},
      {"contact.rough.seed", "integer", "≥ 0", "1", "0", "random seed", ""},
      {"contact.rough.hprime_rms", "number", "> 0", "1", "", "RMS slope h' (one of hprime_rms, h_rms, sa)", ""},
      {"contact.rough.h_rms", "number", "> 0", "m", "", "RMS height", ""},
      {"contact.rough.sa", "number", "> 0", "m", "", "arithmetic mean height Sa", ""},
      {"contact.sphere.radius", "number", "> 0", "m", "", "radius of a sphere added at the cell's centre", ""},
      {"contact.boundary", "choice", "periodic | free", "", "periodic",
       "periodic cell, or a window on an isolated body (frictionless only)", ""},
      {"contact.e_star", "number", "> 0", "Pa", "", "contact modulus E* (1.12)", "--e-star"},
      {"contact.young", "number", "> 0", "Pa", "", "Young's modulus of the elastic flat", ""},
      {"contact.poisson", "number", "(-1, 0.5]", "1", "", "Poisson's ratio ν of the elastic flat", "--poisson"},
      {"contact.mean_pressure", "number", "≥ 0", "Pa", "", "imposed mean pressure", "--pressure"},
      {"contact.normal_load", "number", "≥ 0", "N", "", "imposed normal force on the cell", "--load"},
      {"contact.interference", "number", "any", "m", "", "imposed interference (frictionless)", "--interference"},
      {"contact.friction", "choice", "none | coulomb | tresca", "", "none", "friction law (Appendix A)",
       "--friction"},
      {"contact.friction_coefficient", "number", "≥ 0", "1", "", "Coulomb friction coefficient μ (A.2)", "--mu"},
      {"contact.shear_strength", "number", "≥ 0", "Pa", "", "Tresca shear strength σ_m,T (A.3)", "--shear-strength"},
      {"contact.tangential_pressure", "number", "any", "Pa", "0", "imposed mean tangential traction along x",
       "--tangential-pressure"},
      {"contact.tangential_load", "number", "any", "N", "", "imposed tangential force on the cell along x", ""},
      {"contact.tensile_strength", "number", "> 0", "Pa", "",
       "tensile strength σ_m: crack initiation (4.25) per micro-contact", "--tensile-strength"},
      {"contact.stress_depths", "list", "≥ 0", "m", "", "depths of the subsurface stress fields", ""},
      {"contact.tolerance", "number", "(0, 1)", "1", "1e-12 (frictional 1e-10)", "relative convergence tolerance", ""},
      {"contact.max_iterations", "integer", "≥ 1", "1", "10000 (frictional 20000)", "iteration limit", ""},
      {"contact.connectivity", "choice", "four | eight", "", "four", "neighbours joining a micro-contact", ""},
  };
}

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(ContactStudy)
