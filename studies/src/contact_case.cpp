#include "contact_case.hpp"

#include <algorithm>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/xdmf.hpp"

namespace wearscale::studies {

using namespace bem;

RoughCase read_rough_case(const Config& r, const Grid2D& g) {
  RoughCase rough;
  RoughSurfaceSpec& spec = rough.spec;
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
  if (r.has("hprime_rms")) {
    rough.measure = RoughnessMeasure::HPrimeRms;
    rough.target = r.number("hprime_rms", Range::positive());
  } else if (r.has("h_rms")) {
    rough.measure = RoughnessMeasure::HRms;
    rough.target = r.number("h_rms", Range::positive(), units::length);
  } else {
    rough.measure = RoughnessMeasure::Sa;
    rough.target = r.number("sa", Range::positive(), units::length);
  }
  return rough;
}

Boundary contact_boundary(const Config& c) {
  return c.choice_or("boundary", "periodic", {"periodic", "free"}) == "free" ? Boundary::Free : Boundary::Periodic;
}

double contact_modulus(const Config& c) {
  if (c.has("e_star")) return c.number("e_star", Range::positive(), units::pressure);
  const double e = c.number("young", Range::positive(), units::pressure);
  const double nu = c.number("poisson", Range::open_closed(-1.0, 0.5));
  return e / (1.0 - nu * nu);  // rigid surface on an elastic flat (1.12)
}

NormalCase read_normal_case(const Config& c, const Grid2D& g) {
  NormalCase n;
  n.e_star = contact_modulus(c);
  const int loads = int(c.has("mean_pressure")) + int(c.has("normal_load")) + int(c.has("interference"));
  if (loads != 1)
    throw c.error("mean_pressure", "give exactly one of mean_pressure, normal_load, interference", "one load");
  n.options.tolerance = c.number_or("tolerance", 1e-12, Range::open(0.0, 1.0));
  n.options.max_iterations = static_cast<int>(c.integer_or("max_iterations", 10000, Range::at_least(1)));
  n.connectivity =
      c.choice_or("connectivity", "four", {"four", "eight"}) == "eight" ? Connectivity::Eight : Connectivity::Four;
  n.boundary = contact_boundary(c);
  if (c.has("mean_pressure")) n.p0 = c.number("mean_pressure", Range::non_negative(), units::pressure);
  if (c.has("normal_load")) n.p0 = c.number("normal_load", Range::non_negative(), units::force) / g.area();
  n.imposes_interference = c.has("interference");
  if (n.imposes_interference) n.delta = c.number("interference", Range::any(), units::length);
  return n;
}

ContactResult NormalCase::solve(NormalContact& contact) const {
  return imposes_interference ? contact.solve_interference(delta, options) : contact.solve_mean_pressure(p0, options);
}

void write_normal_study(const Config& config, const NormalCase& n, const RealField& h, const RealField& p,
                        const RealField& gap, const RealField& u, const ContactResult& r,
                        coupling::RunContext& context) {
  const auto& out = context.output_dir();
  const Grid2D g = h.grid();
  const ContactMap map = find_clusters(p, n.connectivity);

  RealField in_contact(g);
  for (std::size_t k = 0; k < g.size(); ++k) in_contact[k] = p[k] > 0.0 ? 1.0 : 0.0;
  const auto h5_path = out / "contact.h5";
  H5Writer h5(h5_path);
  h5.write_field("/surface/height", h, "m");
  h5.write_field("/fields/pressure", p, "Pa");
  h5.write_field("/fields/gap", gap, "m");
  h5.write_field("/fields/displacement", u, "m");
  h5.write_field("/fields/contact", in_contact, "1");
  h5.set_attribute("/", "case_toml", config.to_toml());

  auto report = [&](const std::string& name, double v, const std::string& unit, const std::string& what) {
    context.report(name, v, unit, what);
    h5.write_scalar("/results/" + name, v, unit);
  };
  report("mean_pressure", r.mean_pressure, "Pa", "mean pressure ⟨p⟩");
  report("contact_fraction", r.contact_fraction, "1", "real contact area ratio A/A0");
  report("contact_area", contact_area(p), "m^2", "real contact area A");
  report("interference", r.interference, "m",
         n.boundary == Boundary::Free ? "approach δ of the rigid surface towards the far field"
                                      : "summit depth below the mean deformed surface");
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
  XdmfSidecar sidecar(g);
  sidecar.add(h5, {{"/surface/height", "height"}, {"/fields/pressure", "pressure"}, {"/fields/gap", "gap"},
                   {"/fields/displacement", "displacement"}, {"/fields/contact", "contact"}});
  h5.commit();
  sidecar.write(out / "contact.xdmf", h5_path);
  write_csv(out / "clusters.csv", {"area", "centroid_x", "centroid_y"}, {area, cx, cy}, {"m^2", "m", "m"},
            {"micro-contacts of the solved contact, largest first"});
  for (const auto& f : {h5_path, out / "contact.xdmf", out / "clusters.csv"}) context.add_file(f);
}

}  // namespace wearscale::studies
