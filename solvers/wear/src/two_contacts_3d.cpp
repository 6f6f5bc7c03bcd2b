#include "wearscale/wear/two_contacts_3d.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/wear/energy_balance.hpp"

namespace wearscale::wear {

namespace {
using std::numbers::pi;

void require(bool ok, const char* name, double value, const char* allowed) {
  if (!ok || std::isnan(value))
    throw InputError(fmt::format("3D two-contact wear map: {} = {} is not allowed; allowed: {}", name, value, allowed));
}

void check_poisson(double nu) { require(nu > -1.0 && nu <= 0.5, "Poisson's ratio ν", nu, "−1 < ν ≤ 0.5"); }

void check_map_point(double d_over_l, double dstar_over_l, double c_inter) {
  require(d_over_l > 0.0 && d_over_l <= 1.0, "d/l", d_over_l, "0 < d/l ≤ 1 (the contacts do not overlap)");
  require(dstar_over_l > 0.0 && std::isfinite(dstar_over_l), "d*/l", dstar_over_l, "> 0");
  require(c_inter > 0.0 && std::isfinite(c_inter), "C_inter", c_inter, "> 0 (1/3 … 2/3 by (4.49))");
}
}  // namespace

double interaction_constant(double poisson, double angle) {
  check_poisson(poisson);
  require(std::isfinite(angle), "angle θ", angle, "a finite angle [rad]");
  const double s = std::sin(angle);
  return (1.0 - poisson * s * s) / (2.0 - poisson);  // (4.49)
}

double two_contact_elastic_energy(double diameter, double distance, double angle, double traction,
                                  double shear_modulus, double poisson) {
  check_poisson(poisson);
  require(diameter > 0.0 && std::isfinite(diameter), "diameter d", diameter, "> 0");
  require(distance >= diameter && std::isfinite(distance), "distance l", distance, "l ≥ d (the contacts do not overlap)");
  require(traction > 0.0 && std::isfinite(traction), "traction q", traction, "> 0");
  require(shear_modulus > 0.0 && std::isfinite(shear_modulus), "shear modulus G", shear_modulus, "> 0");
  const double d = diameter, q2 = traction * traction, s = std::sin(angle);
  return (2.0 - poisson) * d * d * d * q2 / (6.0 * shear_modulus) +
         pi * d * d * d * d * q2 * (1.0 - poisson * s * s) / (32.0 * shear_modulus * distance);  // (4.44)
}

const char* name(ParticleCase particle_case) {
  switch (particle_case) {
    case ParticleCase::OneSeparated: return "one_separated";
    case ParticleCase::TwoSeparated: return "two_separated";
    case ParticleCase::Combined: return "combined";
  }
  return "?";
}

double count_constant(ParticleCase particle_case) { return particle_case == ParticleCase::OneSeparated ? 1.0 : 2.0; }

double case_constant(ParticleCase particle_case, double d_over_l) {
  switch (particle_case) {
    case ParticleCase::OneSeparated: return 1.0;
    case ParticleCase::TwoSeparated: return 0.5;
    case ParticleCase::Combined: {
      const double d_over_da = d_over_l / (1.0 + d_over_l);  // d_a = d + l
      return d_over_da * d_over_da;
    }
  }
  return 0.0;
}

double boundary_dstar_over_l(ParticleCase particle_case, double d_over_l, double c_inter) {
  return (count_constant(particle_case) + 3.0 * pi / 8.0 * c_inter * d_over_l) * d_over_l *
         case_constant(particle_case, d_over_l);  // (4.48) with R = 1
}

double energy_ratio_3d(ParticleCase particle_case, double d_over_l, double dstar_over_l, double c_inter) {
  check_map_point(d_over_l, dstar_over_l, c_inter);
  // (C_n + (3π/8) C_inter d/l) (d/d*) C_case, with d/d* = (d/l)/(d*/l)   (4.48)
  return boundary_dstar_over_l(particle_case, d_over_l, c_inter) / dstar_over_l;
}

double energy_ratio_from_energies(ParticleCase particle_case, double diameter, double distance, double angle,
                                  double traction, double shear_modulus, double poisson, double surface_energy) {
  require(surface_energy > 0.0 && std::isfinite(surface_energy), "surface energy γ", surface_energy, "> 0");
  const double e2 = two_contact_elastic_energy(diameter, distance, angle, traction, shear_modulus, poisson);  // (4.44)
  switch (particle_case) {
    case ParticleCase::OneSeparated:  // the other contact keeps E_el,1 (4.33); E_ad,1sep (4.45)
      return (e2 - single_contact_elastic_energy(diameter, traction, shear_modulus, poisson)) /
             adhesive_energy(diameter, surface_energy);
    case ParticleCase::TwoSeparated:  // E_ad,2sep (4.46)
      return e2 / (2.0 * adhesive_energy(diameter, surface_energy));
    case ParticleCase::Combined:  // E_ad,comb (4.47), d_a = d + l
      return e2 / adhesive_energy(diameter + distance, surface_energy);
  }
  return 0.0;
}

const char* name(Region3D region) {
  switch (region) {
    case Region3D::Plastic: return "plastic";
    case Region3D::OneSeparated: return "one_separated";
    case Region3D::TwoSeparated: return "two_separated";
    case Region3D::Combined: return "combined";
  }
  return "?";
}

Region3D classify_3d(double d_over_l, double dstar_over_l, double c_inter) {
  check_map_point(d_over_l, dstar_over_l, c_inter);
  // The most severe case whose boundary lies at or above d*/l (R ≥ 1); nested for d ≤ l.
  if (dstar_over_l <= boundary_dstar_over_l(ParticleCase::Combined, d_over_l, c_inter)) return Region3D::Combined;
  if (dstar_over_l <= boundary_dstar_over_l(ParticleCase::TwoSeparated, d_over_l, c_inter))
    return Region3D::TwoSeparated;
  if (dstar_over_l <= boundary_dstar_over_l(ParticleCase::OneSeparated, d_over_l, c_inter))
    return Region3D::OneSeparated;
  return Region3D::Plastic;
}

}  // namespace wearscale::wear
