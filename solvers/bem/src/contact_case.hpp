#pragma once
// The parts of a [contact] case that the serial study (contact_study.cpp) and
// the slab-distributed one (slab_contact_study.cpp) share: the keys of a
// generated rough surface and of a frictionless load, and the files written
// from the solved fields. Private to the bem layer.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/normal_contact.hpp"
#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/config.hpp"

namespace wearscale::bem {

/// [contact.rough]: the spectrum on grid `g` and the roughness it is scaled to.
struct RoughCase {
  RoughSurfaceSpec spec;
  RoughnessMeasure measure = RoughnessMeasure::HPrimeRms;
  double target = 1.0;
};
RoughCase read_rough_case(const Config& rough, const Grid2D& g);

/// The frictionless keys of [contact]: modulus, boundary, load, tolerance, clusters.
struct NormalCase {
  double e_star = 1.0;
  Boundary boundary = Boundary::Periodic;
  ContactOptions options;
  Connectivity connectivity = Connectivity::Four;
  double p0 = 0.0, delta = 0.0;
  bool imposes_interference = false;
  /// The solve the case asks for (imposed mean pressure or interference).
  ContactResult solve(NormalContact& contact) const;
};
NormalCase read_normal_case(const Config& contact, const Grid2D& g);

/// The headline figures {name: {value, unit, description}} of a solved case
/// (`map`: the micro-contacts, left out when null).
nlohmann::json normal_results(const NormalCase& n, const ContactResult& r, double contact_area, double hprime_rms,
                              const ContactMap* map);

/// contact.h5 (+ .xdmf) and clusters.csv from the whole fields; the headline figures and files.
nlohmann::json write_normal_study(const Config& config, const NormalCase& n, const RealField& h, const RealField& p,
                                  const RealField& gap, const RealField& u, const ContactResult& r,
                                  const std::filesystem::path& out);

}  // namespace wearscale::bem
