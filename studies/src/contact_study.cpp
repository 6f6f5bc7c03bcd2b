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
#include <utility>

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

// The serial strategy: the whole heights (file + rough + sphere), one solver.
RealField build_surface(ContactCase& c) {
  RealField h = c.measured.size() > 0 ? std::move(c.measured) : RealField(c.grid);
  if (c.rough) h = add(h, generate_surface(c.rough->spec, c.rough->measure, c.rough->target));
  if (c.sphere_radius > 0.0) h = add(h, sphere(c.grid, c.sphere_radius, 0.5 * c.grid.lx, 0.5 * c.grid.ly));
  return h;
}

// Frictionless normal contact (Polonsky–Keer).
void run_normal_study(const Config& config, const NormalCase& n, const RealField& h, RunContext& context) {
  const Grid2D g = h.grid();
  log::info("contact: {} , E* = {:g} Pa, {} boundary", g.to_string(), n.e_star, to_string(n.boundary));
  NormalContact contact(h, n.e_star, n.boundary);
  const ContactResult r = n.solve(contact);
  write_normal_study(config, n, h, contact.pressure(), contact.gap(), contact.displacement(), r, context);
}

// Frictional contact (Appendix A): tractions, stick/slip map, displacements,
// surface (and subsurface) stresses, and the criterion (4.25) if σ_m is given.
void run_frictional_study(const Config& config, const FrictionalCase& f, const RealField& h, RunContext& context) {
  const Grid2D g = h.grid();
  log::info("contact: {} , E = {:g} Pa, ν = {:g}, {} friction", g.to_string(), f.young, f.poisson, f.law.to_string());
  FrictionalContact contact(h, f.young, f.poisson, f.law);
  const FrictionalResult r = f.solve(contact, config.section("contact"));
  write_frictional_study(config, f,
                         {h, contact.traction(), contact.displacement(), contact.normal_gap(), contact.slip(),
                          contact.stick_slip_map()},
                         r, context);
}

void run_serial_contact(const Config& config, ContactCase c, RunContext& context) {
  const RealField h = build_surface(c);
  if (c.friction)
    run_frictional_study(config, *c.friction, h, context);
  else
    run_normal_study(config, c.normal, h, context);
}

// One reader ([contact] into a ContactCase), two strategies: serial, or in
// slabs over the ranks under mpirun (contact_slab.hpp).
class ContactStudy final : public Study {
 public:
  std::string name() const override { return "contact"; }
  std::string summary() const override {
    return "normal or frictional contact of a rigid surface (file, rough, sphere) on an elastic flat (BEM)";
  }
  Schema schema() const override;
  // Under mpirun (P > 1) the case is read and checked on every rank before any
  // work; serial runs read it in run(), so a sweep holds no surface.
  std::vector<std::string> prepare(Config& config) override {
    if (mpi::size() > 1) case_ = read_contact_case(config, mpi::size());
    return {};
  }
  bool distributed() const override { return true; }
  void run_other_rank(const Config& config) override { run_slab_contact(config, std::move(case_.value()), nullptr); }
  void run(const Config& config, RunContext& context) override {
    if (case_) return run_slab_contact(config, std::move(*case_), &context);
    run_serial_contact(config, read_contact_case(config, 1), context);
  }

 private:
  std::optional<ContactCase> case_;  // read by prepare() under mpirun
};

Schema ContactStudy::schema() const { return contact_keys().schema("contact"); }

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(ContactStudy)
