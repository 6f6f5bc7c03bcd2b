#include "contact_case.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/crack_initiation.hpp"
#include "wearscale/bem/principal_stresses.hpp"
#include "wearscale/bem/roughness.hpp"
#include "wearscale/bem/subsurface_stress.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/topography_io.hpp"
#include "wearscale/io/xdmf.hpp"
#include "field_descriptions.hpp"

namespace wearscale::studies {

using namespace bem;

namespace {
// Serial: memory per grid point, measured (peak RSS at 1024², with the
// outputs): normal contact about 120 B, frictional with stresses about 580 B.
constexpr double kSerialBytesPerPoint = 160.0, kSerialFrictionalBytesPerPoint = 640.0;
// In slabs: the peak of the solve summed over the ranks (measured at 4096²,
// P = 2: 83 B per point a rank holds, docs/bem.md), and what rank 0 adds to
// gather the four fields, find the micro-contacts and write them.
constexpr double kBytesPerPoint = 112.0, kGatherBytesPerPoint = 88.0;
// A free boundary: the transforms, their spectrum and the two kernels on the
// padded grid (four times the points), the contact's rows once more to move
// them between the two slabs (measured at 2048², P = 2, in place: 188 B per
// point the other rank holds, 228 B on rank 0 with the file's layout).
constexpr double kFreeBytesPerPoint = 230.0;
// Frictional: the solver's 21 fields and the tensor's modes per rank (about
// 250 B per point it holds), and on rank 0 the serial frictional figure.
constexpr double kFrictionalBytesPerPoint = 260.0, kFrictionalGatherBytesPerPoint = kSerialFrictionalBytesPerPoint;
// Above the gather limit each rank also holds its rows of the traction and
// stress spectra, one stress tensor, the surface's principal stresses and two
// fields a depth (measured at 1024², P = 2, two depths: 444 B per point the
// other rank holds).
constexpr double kFrictionalInPlaceBytesPerPoint = 600.0;
}  // namespace

double contact_memory(const ContactCase& c, int ranks, bool root) {
  const double points = static_cast<double>(c.grid.size());
  if (ranks == 1) return (c.friction ? kSerialFrictionalBytesPerPoint : kSerialBytesPerPoint) * points;
  const bool gather = c.grid.size() <= c.gather_limit;
  const double share = c.friction && !gather                  ? kFrictionalInPlaceBytesPerPoint
                       : c.friction                            ? kFrictionalBytesPerPoint
                       : c.normal.boundary == Boundary::Free ? kFreeBytesPerPoint
                                                             : kBytesPerPoint;
  const double gathered_share = c.friction ? kFrictionalGatherBytesPerPoint : kGatherBytesPerPoint;
  return share * points / ranks + (root && gather ? gathered_share * points : 0.0);
}

ContactCase read_contact_case(const Config& config, int ranks) {
  const Config c = config.section("contact");
  ContactCase s;
  s.ranks = ranks;
  contact_keys().read(c, s);
  RunKeys how;  // [run], as the runner reads it
  run_keys().read(config.section("run"), how);
  s.measured_plans = how.fft_planning == PlanRigor::Measure &&
                     s.grid.size() >= std::size_t{512} * 512;  // planning times transforms across the ranks
  s.gather_limit = how.gather_limit;
  const bool file = s.measured.size() > 0;
  const char* size_key = file ? "surface" : "grid";  // what sets the grid
  const std::string size_value = file ? s.given.surface.string() : std::to_string(s.grid.nx);
  // Under mpirun each rank checks its own share (rank 0 adds the gathered
  // fields) against the memory of its machine: the point of the slabs is a
  // grid larger than one machine. Ranks sharing a machine each see all of its
  // free memory, so there the check is per rank, not for the job (an
  // overcommitted job is ended by the system and mpirun ends the others: no
  // wrong answer, no hang).
  const std::string on_ranks =
      ranks == 1 ? "" : fmt::format(" on {} ranks (rank {}'s share)", ranks, mpi::rank());
  require_memory(contact_memory(s, ranks, mpi::is_root()),
                 fmt::format("{}: key '{}' = {}: a contact study of {} × {} points{}", c.where(size_key),
                             c.full_key(size_key), size_value, s.grid.nx, s.grid.ny, on_ranks),
                 ranks == 1 ? "give a smaller grid" : "give a smaller grid or more ranks");
  config.reject_unknown_keys();  // every check before any work
  return s;
}

ContactResult NormalCase::solve(NormalContact& contact) const {
  return imposes_interference ? contact.solve_interference(delta, options) : contact.solve_mean_pressure(p0, options);
}

void report_normal_figures(const NormalCase& n, const ContactResult& r, const NormalFigures& f,
                           const FigureReport& report) {
  report("mean_pressure", r.mean_pressure, "Pa", "mean pressure ⟨p⟩");
  report("contact_fraction", r.contact_fraction, "1", "real contact area ratio A/A0");
  report("contact_area", f.contact_area, "m^2", "real contact area A");
  report("interference", r.interference, "m",
         n.boundary == Boundary::Free ? "approach δ of the rigid surface towards the far field"
                                      : "summit depth below the mean deformed surface");
  report("elastic_energy", r.elastic_energy, "J", "elastic energy ½∫p u dA (2.42)");
  report("clusters", static_cast<double>(f.clusters), "1", "number of micro-contacts");
  report("iterations", r.iterations, "1", "Polonsky–Keer iterations");
  report("error", r.error, "1", "relative orthogonality error Σp|g|/(Σp·h_rms)");
  report("hprime_rms", f.hprime_rms, "1", "RMS slope of the surface (1.6)");
}

void report_frictional_figures(const FrictionalCase& fc, const FrictionalResult& r, const FrictionalFigures& f,
                               const FigureReport& report) {
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
  report("clusters", static_cast<double>(f.clusters), "1", "number of micro-contacts");
  report("iterations", r.iterations, "1", "iterations of Algorithm 1");
  report("bound_updates", r.bound_updates, "1", "updates of the lagged friction limit");
  report("unsettled_points", static_cast<double>(r.unsettled_points), "1",
         "contact points whose friction limit differs from the law's");
  report("error", r.error, "1", "cost (A.14) relative to Σp·h_rms");
  report("max_sigma_I", f.max_sigma_I, "Pa", "largest first principal stress on the surface (4.24)");
  if (!fc.depths.empty())
    report("max_tau_subsurface", f.max_tau, "Pa",
           fmt::format("largest τ_m = (σ_I − σ_III)/2 over the requested depths (at {:g} m)", f.max_tau_depth));
}

ClusterTable::ClusterTable(const std::vector<ContactCluster>& clusters, const std::vector<EdgeCrackCheck>* checks,
                           double sigma_m)
    : names_{"area", "centroid_x", "centroid_y"},
      units_{"m^2", "m", "m"},
      columns_(3),
      comments_{"micro-contacts of the solved contact, largest first"} {
  for (const auto& cl : clusters) {
    columns_[0].push_back(cl.area);
    columns_[1].push_back(cl.centroid_x);
    columns_[2].push_back(cl.centroid_y);
  }
  if (checks == nullptr) return;
  names_.insert(names_.end(), {"trailing_sigma_I", "leading_sigma_III", "crack_initiation"});
  units_.insert(units_.end(), {"Pa", "Pa", "1"});
  columns_.resize(6);
  for (const EdgeCrackCheck& c : *checks) {
    columns_[3].push_back(c.trailing_tension);
    columns_[4].push_back(c.leading_compression);
    columns_[5].push_back(c.initiates() ? 1.0 : 0.0);
    sites_ += columns_[5].back();
  }
  comments_.push_back(fmt::format("crack initiation (4.25) at σ_m = {:g} Pa, from the surface stresses", sigma_m));
}

void ClusterTable::write(H5Writer& h5) const {
  h5.write_table("/clusters", names_, {columns_.begin(), columns_.end()}, units_);
}

std::filesystem::path ClusterTable::write_csv(const std::filesystem::path& folder) const {
  const auto csv = folder / "clusters.csv";
  wearscale::write_csv(csv, names_, {columns_.begin(), columns_.end()}, units_, comments_);
  return csv;
}

void report_crack_sites(const ClusterTable& table, const FigureReport& report) {
  report("crack_initiation_sites", table.crack_sites(), "1", "micro-contacts meeting (4.25) at both edges");
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
  h5.write_field("/surface/height", h, "m", contact_field_description("/surface/height"));
  h5.write_field("/fields/pressure", p, "Pa", contact_field_description("/fields/pressure"));
  h5.write_field("/fields/gap", gap, "m", contact_field_description("/fields/gap"));
  h5.write_field("/fields/displacement", u, "m", contact_field_description("/fields/displacement"));
  h5.write_field("/fields/contact", in_contact, "1", contact_field_description("/fields/contact"));
  h5.set_attribute("/", "case_toml", config.to_toml());

  auto report = [&](const std::string& name, double v, const std::string& unit, const std::string& what) {
    context.report(name, v, unit, what);
    h5.write_scalar("/results/" + name, v, unit);
  };
  report_normal_figures(n, r, {contact_area(p), map.clusters.size(), h_prime_rms(h)}, report);

  const ClusterTable table(map.clusters);
  table.write(h5);
  XdmfSidecar sidecar(g);
  sidecar.add(h5, {{"/surface/height", "height"}, {"/fields/pressure", "pressure"}, {"/fields/gap", "gap"},
                   {"/fields/displacement", "displacement"}, {"/fields/contact", "contact"}});
  h5.commit();
  sidecar.write(out / "contact.xdmf", h5_path);
  const auto csv = table.write_csv(out);
  for (const auto& f : {h5_path, out / "contact.xdmf", csv}) context.add_file(f);
}

FrictionalResult FrictionalCase::solve(FrictionalContact& contact, const Config& c) const {
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
  return r;
}

void write_frictional_study(const Config& config, const FrictionalCase& fc, const FrictionalFields& fields,
                            const FrictionalResult& r, coupling::RunContext& context) {
  const auto& out = context.output_dir();
  const Grid2D g = fields.height.grid();
  const ContactMap map = find_clusters(fields.traction.z, fc.connectivity);

  SubsurfaceStress solid(g, fc.poisson);
  solid.set_traction(fields.traction);
  StressField stress(g);
  PrincipalStresses surface(g), deep(g);
  solid.stress(0.0, stress);
  principal_stresses(stress, surface);

  RealField in_contact(g);
  for (std::size_t k = 0; k < g.size(); ++k) in_contact[k] = fields.traction.z[k] > 0.0 ? 1.0 : 0.0;
  const auto h5_path = out / "contact.h5";
  H5Writer h5(h5_path);
  std::vector<XdmfField> xdmf;
  auto field = [&](const std::string& path, const RealField& f, const char* unit, const std::string& name) {
    h5.write_field(path, f, unit, contact_field_description(path));
    xdmf.push_back({path, name});
  };
  field("/surface/height", fields.height, "m", "height");
  field("/fields/pressure", fields.traction.z, "Pa", "p_N");
  field("/fields/traction_x", fields.traction.x, "Pa", "p_x");
  field("/fields/traction_y", fields.traction.y, "Pa", "p_y");
  field("/fields/stick_slip", fields.stick_slip, "1", "stick_slip");
  h5.set_attribute("/fields/stick_slip", "values", "0 open, 1 stick, 2 slip");
  field("/fields/gap", fields.gap, "m", "gap");
  field("/fields/slip_x", fields.slip.x, "m", "slip_x");
  field("/fields/slip_y", fields.slip.y, "m", "slip_y");
  field("/fields/displacement", fields.displacement.z, "m", "u_z");
  field("/fields/displacement_x", fields.displacement.x, "m", "u_x");
  field("/fields/displacement_y", fields.displacement.y, "m", "u_y");
  field("/fields/contact", in_contact, "1", "contact");
  field("/stress/surface/sigma_I", surface.first, "Pa", "sigma_I");
  field("/stress/surface/sigma_III", surface.third, "Pa", "sigma_III");
  field("/stress/surface/tau_max", surface.max_shear, "Pa", "tau_max");
  double deep_tau = 0.0, deep_tau_depth = 0.0;
  for (std::size_t d = 0; d < fc.depths.size(); ++d) {
    solid.stress(fc.depths[d], stress);
    principal_stresses(stress, deep);
    const std::string group = fmt::format("/stress/depth_{}", d);
    field(group + "/sigma_I", deep.first, "Pa", fmt::format("sigma_I_depth_{}", d));
    field(group + "/tau_max", deep.max_shear, "Pa", fmt::format("tau_max_depth_{}", d));
    h5.set_attribute(group, "depth", fc.depths[d]);
    const double m = *std::max_element(deep.max_shear.begin(), deep.max_shear.end());
    if (m > deep_tau) {
      deep_tau = m;
      deep_tau_depth = fc.depths[d];
    }
  }
  h5.set_attribute("/", "case_toml", config.to_toml());

  auto report = [&](const std::string& name, double v, const std::string& unit, const std::string& what) {
    context.report(name, v, unit, what);
    h5.write_scalar("/results/" + name, v, unit);
  };
  report_frictional_figures(fc, r,
                            {map.clusters.size(), *std::max_element(surface.first.begin(), surface.first.end()),
                             deep_tau, deep_tau_depth},
                            report);

  // Micro-contacts, with (4.25) at their edges if σ_m is given.
  std::vector<EdgeCrackCheck> checks;
  if (fc.crack && !map.clusters.empty())
    checks = crack_initiation(map, surface, fc.crack_direction_x(), 0.0, fc.sigma_m);
  const ClusterTable table(map.clusters, fc.crack ? &checks : nullptr, fc.sigma_m);
  if (fc.crack) report_crack_sites(table, report);
  table.write(h5);
  XdmfSidecar sidecar(g);
  sidecar.add(h5, xdmf);
  h5.commit();
  sidecar.write(out / "contact.xdmf", h5_path);
  const auto csv = table.write_csv(out);
  for (const auto& f : {h5_path, out / "contact.xdmf", csv}) context.add_file(f);
}


}  // namespace wearscale::studies
