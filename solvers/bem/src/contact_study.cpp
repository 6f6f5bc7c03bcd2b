#include "wearscale/bem/contact_study.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/bem/topography_io.hpp"
#include "wearscale/core/csv.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/hdf5_file.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/xdmf.hpp"

namespace wearscale::bem {

namespace {

RealField build_surface(const Config& c) {
  RealField h;
  if (c.has("surface")) {
    const std::string dataset = c.string_or("dataset", default_surface_dataset);
    TopographySize size;
    if (c.has("size")) size.lx = size.ly = c.number("size", Range::positive(), units::length);
    h = read_topography(c.string("surface"), dataset, size);
  } else {
    const long n = c.integer("grid", Range::closed(8, 16384));
    const double l = c.number("size", Range::positive(), units::length);
    h = RealField(Grid2D::square(static_cast<std::size_t>(n), l));
  }
  const Grid2D g = h.grid();
  if (c.has("rough")) {
    const Config r = c.section("rough");
    RoughSurfaceSpec spec;
    spec.grid = g;
    // Ranges checked here so messages name the case key; the generator checks them again.
    const double nyquist = static_cast<double>(std::min(g.nx, g.ny) / 2);
    spec.hurst = r.number("hurst", Range::open_closed(0.0, 1.0));
    spec.k_l = r.number("k_l", Range::open_closed(0.0, nyquist));
    spec.k_r = r.number_or("k_r", spec.k_l, Range::closed(spec.k_l, nyquist));
    spec.k_s = r.number("k_s", Range::closed(spec.k_r, nyquist));
    spec.seed = static_cast<std::uint64_t>(r.integer_or("seed", 0, Range::non_negative()));
    const int targets = int(r.has("hprime_rms")) + int(r.has("h_rms")) + int(r.has("sa"));
    if (targets != 1) throw r.error("hprime_rms", "give exactly one of hprime_rms, h_rms, sa", "one roughness target");
    RealField rough;
    if (r.has("hprime_rms"))
      rough = generate_surface(spec, RoughnessMeasure::HPrimeRms, r.number("hprime_rms", Range::positive()));
    else if (r.has("h_rms"))
      rough = generate_surface(spec, RoughnessMeasure::HRms, r.number("h_rms", Range::positive(), units::length));
    else
      rough = generate_surface(spec, RoughnessMeasure::Sa, r.number("sa", Range::positive(), units::length));
    h = add(h, rough);
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

double contact_modulus(const Config& c) {
  if (c.has("e_star")) return c.number("e_star", Range::positive(), units::pressure);
  const double e = c.number("young", Range::positive(), units::pressure);
  const double nu = c.number("poisson", Range::open_closed(-1.0, 0.5));
  return e / (1.0 - nu * nu);  // rigid surface on an elastic flat (1.12)
}

}  // namespace

nlohmann::json run_contact_study(const Config& config, const std::filesystem::path& out) {
  const Config c = config.section("contact");
  const RealField h = build_surface(c);
  const Grid2D g = h.grid();
  const double e_star = contact_modulus(c);
  const int loads = int(c.has("mean_pressure")) + int(c.has("normal_load")) + int(c.has("interference"));
  if (loads != 1)
    throw c.error("mean_pressure", "give exactly one of mean_pressure, normal_load, interference", "one load");
  ContactOptions options;
  options.tolerance = c.number_or("tolerance", 1e-12, Range::open(0.0, 1.0));
  options.max_iterations = static_cast<int>(c.integer_or("max_iterations", 10000, Range::at_least(1)));
  const auto connectivity =
      c.choice_or("connectivity", "four", {"four", "eight"}) == "eight" ? Connectivity::Eight : Connectivity::Four;
  double p0 = 0.0, delta = 0.0;
  if (c.has("mean_pressure")) p0 = c.number("mean_pressure", Range::non_negative(), units::pressure);
  if (c.has("normal_load")) p0 = c.number("normal_load", Range::non_negative(), units::force) / g.area();
  if (c.has("interference")) delta = c.number("interference", Range::any(), units::length);
  config.reject_unknown_keys();  // every check before any work

  log::info("contact: {} , E* = {:g} Pa", g.to_string(), e_star);
  NormalContact contact(h, e_star);
  const ContactResult r =
      c.has("interference") ? contact.solve_interference(delta, options) : contact.solve_mean_pressure(p0, options);
  const ContactMap map = find_clusters(contact.pressure(), connectivity);

  RealField in_contact(g);
  for (std::size_t k = 0; k < g.size(); ++k) in_contact[k] = contact.pressure()[k] > 0.0 ? 1.0 : 0.0;
  const auto h5_path = out / "contact.h5";
  H5Writer h5(h5_path);
  h5.write_field("/surface/height", h, "m");
  h5.write_field("/fields/pressure", contact.pressure(), "Pa");
  h5.write_field("/fields/gap", contact.gap(), "m");
  h5.write_field("/fields/displacement", contact.displacement(), "m");
  h5.write_field("/fields/contact", in_contact, "1");
  h5.set_attribute("/", "case_toml", config.to_toml());

  nlohmann::json results = nlohmann::json::object();
  auto report = [&](const std::string& name, double v, const std::string& unit, const std::string& what) {
    results[name] = {{"value", v}, {"unit", unit}, {"description", what}};
    h5.write_scalar("/results/" + name, v, unit);
  };
  report("mean_pressure", r.mean_pressure, "Pa", "mean pressure ⟨p⟩");
  report("contact_fraction", r.contact_fraction, "1", "real contact area ratio A/A0");
  report("contact_area", contact_area(contact.pressure()), "m^2", "real contact area A");
  report("interference", r.interference, "m", "summit depth below the mean deformed surface");
  report("elastic_energy", r.elastic_energy, "J", "elastic energy ½∫p u dA (2.42)");
  report("clusters", static_cast<double>(map.clusters.size()), "1", "number of micro-contacts");
  report("iterations", r.iterations, "1", "Polonsky–Keer iterations");
  report("error", r.error, "1", "relative orthogonality error Σp|g|/(Σp·h_rms)");
  report("hprime_rms", h_prime_rms(h), "1", "RMS slope of the surface (1.6)");

  std::vector<double> area, cx, cy;
  for (const auto& cl : map.clusters) {
    area.push_back(cl.area);
    cx.push_back(cl.centroid_x);
    cy.push_back(cl.centroid_y);
  }
  h5.write_table("/clusters", {"area", "centroid_x", "centroid_y"}, {area, cx, cy}, {"m^2", "m", "m"});
  h5.commit();
  write_xdmf(out / "contact.xdmf", h5_path, g,
             {{"/surface/height", "height"}, {"/fields/pressure", "pressure"}, {"/fields/gap", "gap"},
              {"/fields/displacement", "displacement"}, {"/fields/contact", "contact"}});
  write_csv(out / "clusters.csv", {"area_m2", "centroid_x_m", "centroid_y_m"}, {area, cx, cy},
            {"micro-contacts of the solved contact, largest first"});
  return {{"results", results},
          {"files", {h5_path.string(), (out / "contact.xdmf").string(), (out / "clusters.csv").string()}}};
}

}  // namespace wearscale::bem
