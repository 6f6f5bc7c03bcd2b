#include "wearscale/bem/slab_contact_study.hpp"

#include <memory>

#include <fmt/format.h>

#include "contact_case.hpp"
#include "wearscale/bem/slab_half_space.hpp"
#include "wearscale/bem/slab_surface.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/mpi.hpp"

namespace wearscale::bem {

namespace {
// Memory per grid point of the slab study, summed over the ranks (measured
// during the solve at 4096², P = 2: 0.65–0.68 GiB per rank for its 8.4
// million points, 83 B per point; docs/bem.md) with a margin, and what rank 0
// adds to gather the four fields, find the micro-contacts and write them
// (measured there: about 88 B per grid point with its slab still allocated,
// which is now freed first).
constexpr double kBytesPerPoint = 100.0, kGatherBytesPerPoint = 88.0;

// The whole field on rank 0 (an empty one elsewhere) from every rank's rows.
RealField gathered(const RealField& slab, const Grid2D& g) {
  RealField whole(mpi::is_root() ? g : Grid2D(0, g.ny, 1.0, g.ly));
  mpi::gather(slab.values(), whole.values());
  return whole;
}
}  // namespace

nlohmann::json run_slab_contact_study(const Config& config, const std::filesystem::path& out) {
  const Config c = config.section("contact");
  const int ranks = mpi::size();
  if (c.choice_or("friction", "none", {"none", "coulomb", "tresca"}) != "none")
    throw c.error("friction",
                  fmt::format("frictional contact is not distributed over MPI ranks yet ({} ranks started)", ranks),
                  "\"none\" under mpirun; frictional contact on one rank (without mpirun)");
  if (c.has("surface"))
    throw c.error("surface", "a measured surface is not read in slabs over MPI ranks yet",
                  "[contact.rough] and/or [contact.sphere] under mpirun; a file on one rank (without mpirun)");
  const long n = c.integer("grid", Range::closed(8, 16384));
  const double points = static_cast<double>(n) * static_cast<double>(n);
  const Grid2D g = Grid2D::square(static_cast<std::size_t>(n), c.number("size", Range::positive(), units::length));
  const NormalCase normal = read_normal_case(c, g);
  if (normal.boundary == Boundary::Free)
    throw c.error("boundary", "a free boundary is not distributed over MPI ranks yet",
                  "\"periodic\" under mpirun; \"free\" on one rank (without mpirun)");
  const bool rough = c.has("rough"), cap = c.has("sphere");
  const RoughCase spectrum = rough ? read_rough_case(c.section("rough"), g) : RoughCase{};
  const double radius = cap ? c.number("sphere.radius", Range::positive(), units::length) : 0.0;
  if (!rough && !cap)
    throw c.error("surface", "no surface: give a [contact.rough] or a [contact.sphere] table", "rough and/or sphere");
  const bool gather = g.size() <= slab_gather_limit;
  require_memory(kBytesPerPoint * points / ranks + (mpi::is_root() && gather ? kGatherBytesPerPoint * points : 0.0),
                 fmt::format("{}: key '{}' = {}: a contact study of {} × {} points on {} ranks", c.where("grid"),
                             c.full_key("grid"), n, n, n, ranks),
                 "give a smaller grid or more ranks");
  config.reject_unknown_keys();  // every check before any work

  log::info("contact: {} , E* = {:g} Pa, periodic boundary, in slabs over {} ranks", g.to_string(), normal.e_star,
            ranks);
  // Measured plans pay off from 512² (planning times transforms across the ranks).
  auto body = std::make_unique<SlabHalfSpace>(g, normal.e_star,
                                              g.size() >= 512 * 512 ? PlanRigor::Measure : PlanRigor::Estimate);
  const std::size_t first = body->first_row(), rows = body->rows();
  SlabFFT& fft = body->fft();
  RealField h(body->local_grid());  // 0 + rough + sphere, as the serial study adds them
  if (rough) h = add(h, generate_surface_slab(spectrum.spec, spectrum.measure, spectrum.target, fft));
  if (cap) h = add(h, sphere_rows(g, first, rows, radius, 0.5 * g.lx, 0.5 * g.ly));
  const double hprime = gather ? 0.0 : roughness_slab(h, g, RoughnessMeasure::HPrimeRms, fft);
  auto contact = std::make_unique<NormalContact>(std::move(body), h, normal.e_star);
  const ContactResult r = normal.solve(*contact);

  if (gather) {
    const RealField whole_h = gathered(h, g), p = gathered(contact->pressure(), g);
    const RealField gap = gathered(contact->gap(), g), u = gathered(contact->displacement(), g);
    contact.reset();  // the slabs are gathered: rank 0 writes from the whole fields alone
    h = RealField();
    if (!mpi::is_root()) return nullptr;
    return write_normal_study(config, normal, whole_h, p, gap, u, r, out);
  }
  if (!mpi::is_root()) return nullptr;
  log::warn("contact: {} points are more than rank 0 gathers ({}): only the headline figures are written (no "
            "contact.h5, no micro-contacts)",
            g.size(), slab_gather_limit);
  return {{"results", normal_results(normal, r, r.contact_fraction * g.area(), hprime, nullptr)},
          {"files", nlohmann::json::array()}};
}

}  // namespace wearscale::bem
