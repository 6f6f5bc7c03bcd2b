#include "contact_slab.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/frictional_contact.hpp"
#include "wearscale/bem/slab_clusters.hpp"
#include "wearscale/bem/slab_crack_initiation.hpp"
#include "wearscale/bem/slab_free_half_space.hpp"
#include "wearscale/bem/slab_half_space.hpp"
#include "wearscale/bem/slab_surface.hpp"
#include "wearscale/bem/slab_subsurface_stress.hpp"
#include "wearscale/bem/principal_stresses.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/laid_out_file.hpp"
#include "wearscale/io/xdmf.hpp"
#include "field_descriptions.hpp"

namespace wearscale::studies {

using namespace bem;

namespace {
// The whole field on rank 0 (an empty one elsewhere) from every rank's rows.
RealField gathered(const RealField& slab, const Grid2D& g) {
  RealField whole(mpi::is_root() ? g : Grid2D(0, g.ny, 1.0, g.ly));
  mpi::gather(slab.values(), whole.values());
  return whole;
}
}  // namespace

namespace {
VectorField gathered(const VectorField& slab, const Grid2D& g) {
  VectorField whole(mpi::is_root() ? g : Grid2D(0, g.ny, 1.0, g.ly));
  whole.x = gathered(slab.x, g);
  whole.y = gathered(slab.y, g);
  whole.z = gathered(slab.z, g);
  return whole;
}

// A slab solve stops on every rank at the same iteration (ContactOptions::stop).
template <class Solve>
auto together(Solve solve) {
  try {
    return solve();
  } catch (const Interrupted& e) {
    throw mpi::JointInterruption(e.what());
  }
}

// This rank's rows of the measured surface (zero heights without one); the whole surface is freed.
RealField own_rows(ContactCase& s, const Grid2D& local, std::size_t first) {
  RealField h(local);
  if (s.measured.size() == 0) return h;
  const auto whole = s.measured.values();
  std::copy_n(whole.begin() + static_cast<std::ptrdiff_t>(first * local.ny), h.size(), h.values().begin());
  s.measured = RealField();
  return h;
}

}  // namespace

namespace {
// One rank's rows of a field of contact.h5.
struct SlabField {
  const char* dataset;
  const char* name;  // in ParaView
  const char* unit;
  const RealField* rows;
};
using Report = FigureReport;

// contact.h5 of a grid no rank gathers (collective): rank 0 lays it out on
// disk (the case, the headline figures through `results`, every field
// reserved, their views for ParaView), every rank writes its rows of each
// field in place, and rank 0 commits it with the run's other outputs. A
// failure to write on any rank is every rank's refusal (status 2), and the
// file is removed.
void write_fields_in_place(const Config& config, const Grid2D& g, std::size_t first_row,
                           const std::vector<SlabField>& fields, coupling::RunContext* context,
                           const std::function<void(const Report&)>& results,
                           const std::function<void(H5Writer&)>& tables) {
  static_assert(std::endian::native == std::endian::little, "the fields are written in place as little-endian doubles");
  std::optional<LaidOutFile> file;  // rank 0's
  std::vector<double> offsets(fields.size());  // bytes, below 2^53: exact
  std::string partial;
  std::vector<XdmfField> views;  // ParaView's: added by the child that lays the file out, named by the sidecar here
  for (const SlabField& f : fields) views.push_back({f.dataset, f.name});
  mpi::refuse_together([&] {
    if (context == nullptr) return;
    // The headline figures are reported here, in this process; the child
    // that lays the file out writes them into it.
    std::vector<std::tuple<std::string, double, std::string>> figures;
    results([&](const std::string& name, double v, const std::string& unit, const std::string& what) {
      context->report(name, v, unit, what);
      figures.emplace_back(name, v, unit);
    });
    file.emplace(context->output_dir() / "contact.h5", [&](H5Writer& h5) {
      std::vector<std::uint64_t> at;
      for (const SlabField& f : fields)
        at.push_back(h5.reserve_field(f.dataset, g, f.unit, contact_field_description(f.dataset)));
      h5.set_attribute("/", "case_toml", config.to_toml());
      for (const auto& [name, v, unit] : figures) h5.write_scalar("/results/" + name, v, unit);
      tables(h5);
      XdmfSidecar(g).add(h5, views);
      return at;
    });
    for (std::size_t k = 0; k < fields.size(); ++k) offsets[k] = static_cast<double>(file->offsets()[k]);
    partial = file->partial().string();
  });
  mpi::broadcast(offsets);
  mpi::broadcast(partial);
  mpi::refuse_together([&] {
    for (std::size_t k = 0; k < fields.size(); ++k) {
      const RealField& rows = *fields[k].rows;
      const auto at = static_cast<std::uint64_t>(offsets[k]) + sizeof(double) * first_row * g.ny;
      try {
        write_in_place(partial, at, rows.data(), rows.size() * sizeof(double));
      } catch (const OutputError& e) {
        throw OutputError(fmt::format("{} (rank {}'s rows of {}); contact.h5 was not written", e.what(), mpi::rank(),
                                      fields[k].dataset));
      }
    }
  });
  if (context == nullptr) return;
  file->commit();
  XdmfSidecar(g).add_written(views).write(context->output_dir() / "contact.xdmf", file->final_path());
  for (const auto& f : {file->final_path(), context->output_dir() / "contact.xdmf"}) context->add_file(f);
}
// Coulomb or Tresca friction: the one FrictionalContact on a SlabHalfSpace of
// the whole tensor. Up to the gather limit rank 0 gathers the fields and
// writes the serial study's files; above it every rank computes its rows of
// the stresses (SlabSubsurfaceStress, the body's transforms) and writes its
// rows of every field in place, and the micro-contacts are joined across the
// slabs. A slab solve stops on every rank at the same iteration (ContactOptions::stop).
void run_slab_friction(const Config& config, ContactCase& s, coupling::RunContext* context) {
  const Grid2D& g = s.grid;
  const FrictionalCase& f = *s.friction;
  log::info("contact: {} , E = {:g} Pa, ν = {:g}, {} friction, periodic boundary, in slabs over {} MPI ranks",
            g.to_string(), f.young, f.poisson, f.law.to_string(), mpi::size());
  auto body = std::make_unique<SlabHalfSpace>(g, f.young, f.poisson,
                                              s.measured_plans ? PlanRigor::Measure : PlanRigor::Estimate);
  const std::size_t first = body->first_row(), rows = body->rows();
  SlabFFT& fft = body->fft();  // owned by the body, which the contact keeps
  RealField h = own_rows(s, body->local_grid(), first);  // file + rough + sphere, as the serial study adds them
  if (s.rough) h = add(h, generate_surface_slab(s.rough->spec, s.rough->measure, s.rough->target, fft));
  if (s.sphere_radius > 0.0) h = add(h, sphere_rows(g, first, rows, s.sphere_radius, 0.5 * g.lx, 0.5 * g.ly));
  FrictionalContact contact(std::move(body), h, f.law);
  const FrictionalResult r = together([&] { return f.solve(contact, config.section("contact")); });
  if (g.size() <= s.gather_limit) {
    RealField whole_h = gathered(h, g);
    h = RealField();
    const VectorField traction = gathered(contact.traction(), g), u = gathered(contact.displacement(), g);
    const VectorField slip = gathered(contact.slip(), g);
    const RealField gap = gathered(contact.normal_gap(), g), map = gathered(contact.stick_slip_map(), g);
    if (context != nullptr) write_frictional_study(config, f, {whole_h, traction, u, gap, slip, map}, r, *context);
    return;
  }
  if (context != nullptr)
    log::info("contact: {} points are more than rank 0 gathers ({}, [run] gather_limit): every rank computes its rows "
              "of the stresses and writes its rows of the fields into contact.h5, the micro-contacts are joined "
              "across the slabs",
              g.size(), s.gather_limit);
  const VectorField& traction = contact.traction();
  const Grid2D& local = traction.grid();
  // The stresses at the surface and at each depth asked for, as the serial study writes them.
  SlabSubsurfaceStress solid(g, f.poisson, fft);
  solid.set_traction(traction);
  StressField stress(local);
  PrincipalStresses surface(local);
  solid.stress(0.0, stress);
  principal_stresses(stress, surface);
  std::vector<RealField> deep_first, deep_shear;
  double deep_tau = 0.0, deep_tau_depth = 0.0;
  for (const double depth : f.depths) {
    PrincipalStresses deep(local);
    solid.stress(depth, stress);
    principal_stresses(stress, deep);
    double m = 0.0;
    for (double v : deep.max_shear) m = std::max(m, v);
    m = mpi::max(m);
    if (m > deep_tau) {
      deep_tau = m;
      deep_tau_depth = depth;
    }
    deep_first.push_back(std::move(deep.first));
    deep_shear.push_back(std::move(deep.max_shear));
  }
  double max_sigma = -std::numeric_limits<double>::infinity();
  for (double v : surface.first) max_sigma = std::max(max_sigma, v);
  max_sigma = mpi::max(max_sigma);
  RealField in_contact(local);
  for (std::size_t k = 0; k < in_contact.size(); ++k) in_contact[k] = traction.z[k] > 0.0 ? 1.0 : 0.0;
  // The micro-contacts joined across the slabs, with (4.25) at their edges if σ_m is given.
  SlabContactMap map = label_clusters_slab(traction.z, first, g, f.connectivity);
  std::vector<EdgeCrackCheck> checks;
  if (f.crack) checks = crack_initiation_slab(map, surface, first, g, f.crack_direction_x(), 0.0, f.sigma_m);
  map.label = std::vector<int>();  // 4 B a point, not needed for writing
  const ClusterTable table(map.clusters, f.crack ? &checks : nullptr, f.sigma_m);  // rank 0's (the sites on every rank)
  const VectorField &u = contact.displacement(), &slip = contact.slip();
  std::vector<SlabField> fields = {{"/surface/height", "height", "m", &h},
                                   {"/fields/pressure", "p_N", "Pa", &traction.z},
                                   {"/fields/traction_x", "p_x", "Pa", &traction.x},
                                   {"/fields/traction_y", "p_y", "Pa", &traction.y},
                                   {"/fields/stick_slip", "stick_slip", "1", &contact.stick_slip_map()},
                                   {"/fields/gap", "gap", "m", &contact.normal_gap()},
                                   {"/fields/slip_x", "slip_x", "m", &slip.x},
                                   {"/fields/slip_y", "slip_y", "m", &slip.y},
                                   {"/fields/displacement", "u_z", "m", &u.z},
                                   {"/fields/displacement_x", "u_x", "m", &u.x},
                                   {"/fields/displacement_y", "u_y", "m", &u.y},
                                   {"/fields/contact", "contact", "1", &in_contact},
                                   {"/stress/surface/sigma_I", "sigma_I", "Pa", &surface.first},
                                   {"/stress/surface/sigma_III", "sigma_III", "Pa", &surface.third},
                                   {"/stress/surface/tau_max", "tau_max", "Pa", &surface.max_shear}};
  std::vector<std::string> deep_names;  // the datasets' names and ParaView's, kept alive for the list
  for (std::size_t d = 0; d < f.depths.size(); ++d)
    for (const char* what : {"sigma_I", "tau_max"}) {
      deep_names.push_back(fmt::format("/stress/depth_{}/{}", d, what));
      deep_names.push_back(fmt::format("{}_depth_{}", what, d));
    }
  for (std::size_t d = 0; d < f.depths.size(); ++d) {
    fields.push_back({deep_names[4 * d].c_str(), deep_names[4 * d + 1].c_str(), "Pa", &deep_first[d]});
    fields.push_back({deep_names[4 * d + 2].c_str(), deep_names[4 * d + 3].c_str(), "Pa", &deep_shear[d]});
  }
  write_fields_in_place(config, g, first, fields, context, [&](const Report& report) {
    report_frictional_figures(f, r, {map.count, max_sigma, deep_tau, deep_tau_depth}, report);
    if (f.crack) report_crack_sites(table, report);
  }, [&](H5Writer& h5) {
    h5.set_attribute("/fields/stick_slip", "values", "0 open, 1 stick, 2 slip");
    for (std::size_t d = 0; d < f.depths.size(); ++d)
      h5.set_attribute(fmt::format("/stress/depth_{}", d), "depth", f.depths[d]);
    table.write(h5);
  });
  if (context != nullptr) context->add_file(table.write_csv(context->output_dir()));
}
}  // namespace

void run_slab_contact(const Config& config, ContactCase s, coupling::RunContext* context) {
  if (s.friction) return run_slab_friction(config, s, context);
  const Grid2D& g = s.grid;
  const NormalCase& normal = s.normal;
  const bool free = normal.boundary == Boundary::Free;
  log::info("contact: {} , E* = {:g} Pa, {} boundary, in slabs over {} MPI ranks", g.to_string(), normal.e_star,
            to_string(normal.boundary), mpi::size());
  const PlanRigor rigor = s.measured_plans ? PlanRigor::Measure : PlanRigor::Estimate;
  // The transforms of the contact's grid, for its rough surface and its
  // slope: the periodic body's own; a free body transforms the padded grid,
  // so the contact's get their own (made when needed, freed for the solve).
  std::unique_ptr<NormalOperator> body;
  std::unique_ptr<SlabFFT> own_fft;
  SlabFFT* periodic_fft = nullptr;
  if (free) {
    body = std::make_unique<SlabFreeHalfSpace>(g, normal.e_star, rigor);
  } else {
    auto periodic = std::make_unique<SlabHalfSpace>(g, normal.e_star, rigor);
    periodic_fft = &periodic->fft();  // owned by the body, which the contact keeps
    body = std::move(periodic);
  }
  auto transforms = [&]() -> SlabFFT& {
    if (periodic_fft != nullptr) return *periodic_fft;
    if (!own_fft) own_fft = std::make_unique<SlabFFT>(g.nx, g.ny, PlanRigor::Estimate);
    return *own_fft;
  };
  const std::size_t first = body->first_row(), rows = body->local_grid().nx;
  RealField h = own_rows(s, body->local_grid(), first);  // file + rough + sphere, as the serial study adds them
  if (s.rough) h = add(h, generate_surface_slab(s.rough->spec, s.rough->measure, s.rough->target, transforms()));
  if (s.sphere_radius > 0.0) h = add(h, sphere_rows(g, first, rows, s.sphere_radius, 0.5 * g.lx, 0.5 * g.ly));
  own_fft.reset();
  NormalContact contact(std::move(body), h, normal.e_star);
  // A free window too small for its contact is every rank's refusal, said once.
  ContactResult r;
  mpi::refuse_together([&] { r = together([&] { return normal.solve(contact); }); });

  if (g.size() <= s.gather_limit) {
    RealField whole_h = gathered(h, g);
    h = RealField();  // each slab freed once gathered: rank 0 holds the whole fields next
    const RealField p = gathered(contact.pressure(), g), gap = gathered(contact.gap(), g);
    const RealField u = gathered(contact.displacement(), g);
    if (context != nullptr) write_normal_study(config, normal, whole_h, p, gap, u, r, *context);
    return;
  }
  // Above the gather limit: the headline figures from the slabs (collective),
  // the fields written in place, the micro-contacts joined across the slabs.
  const double hprime = roughness_slab(h, g, RoughnessMeasure::HPrimeRms, transforms());
  own_fft.reset();
  RealField in_contact(h.grid());
  long long touching = 0;
  for (std::size_t k = 0; k < in_contact.size(); ++k) {
    in_contact[k] = contact.pressure()[k] > 0.0 ? 1.0 : 0.0;
    touching += contact.pressure()[k] > 0.0 ? 1 : 0;
  }
  const double area = static_cast<double>(mpi::sum(touching)) * g.cell_area();
  if (context != nullptr)
    log::info("contact: {} points are more than rank 0 gathers ({}, [run] gather_limit): every rank writes its rows "
              "of the fields into contact.h5, the micro-contacts are joined across the slabs",
              g.size(), s.gather_limit);
  const std::vector<ContactCluster> clusters = find_clusters_slab(contact.pressure(), first, g, normal.connectivity);
  const ClusterTable table(clusters);  // rank 0's
  const std::vector<SlabField> fields = {{"/surface/height", "height", "m", &h},
                                         {"/fields/pressure", "pressure", "Pa", &contact.pressure()},
                                         {"/fields/gap", "gap", "m", &contact.gap()},
                                         {"/fields/displacement", "displacement", "m", &contact.displacement()},
                                         {"/fields/contact", "contact", "1", &in_contact}};
  write_fields_in_place(config, g, first, fields, context, [&](const Report& report) {
    report_normal_figures(normal, r, {area, clusters.size(), hprime}, report);
  }, [&](H5Writer& h5) {
    table.write(h5);
  });
  if (context != nullptr) context->add_file(table.write_csv(context->output_dir()));
}

}  // namespace wearscale::studies
