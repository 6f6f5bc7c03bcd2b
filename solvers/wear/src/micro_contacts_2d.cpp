#include "wearscale/wear/micro_contacts_2d.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::wear {

namespace {
using std::numbers::pi;

void require(bool ok, const char* what, const char* name, double value, const char* allowed) {
  if (!ok || std::isnan(value))
    throw InputError(fmt::format("{}: {} = {} is not allowed; allowed: {}", what, name, value, allowed));
}

void check_poisson(const char* what, double nu) {
  require(nu > -1.0 && nu <= 0.5, what, "Poisson's ratio ν", nu, "−1 < ν ≤ 0.5");
}

void check_sizes(double real_size, double apparent_size, double critical_size) {
  const char* what = "2D wear map";
  require(real_size >= 0.0 && std::isfinite(real_size), what, "real contact size d_r", real_size, "≥ 0");
  require(apparent_size > 0.0 && std::isfinite(apparent_size), what, "apparent contact size d_a", apparent_size,
          "> 0");
  require(critical_size > 0.0 && std::isfinite(critical_size), what, "critical size d*", critical_size, "> 0");
}
}  // namespace

double MicroContactRow::real_size() const { return count * size; }  // (3.18)

double MicroContactRow::apparent_size() const { return count * size + (count - 1) * spacing; }  // (3.19)

void check(const MicroContactRow& row) {
  const char* what = "row of micro-contacts";
  require(row.count >= 1, what, "number N", row.count, "N ≥ 1");
  require(row.size > 0.0 && std::isfinite(row.size), what, "size d", row.size, "d > 0");
  require(row.spacing >= 0.0 && std::isfinite(row.spacing), what, "spacing λ", row.spacing, "λ ≥ 0");
}

double row_elastic_energy_2d(const MicroContactRow& row, double traction, double young, double poisson,
                             double thickness, double domain_factor) {
  check(row);
  check_poisson("2D elastic energy", poisson);
  const double n = row.count, d = row.size, q = traction;
  return (1.0 - poisson * poisson) * thickness * n * n * d * d * q * q * domain_factor / (pi * young);  // (3.15)
}

double adhesive_energy_2d(double particle_size, double surface_energy, double thickness) {
  return pi * surface_energy * thickness * particle_size;  // (3.16)
}

double critical_size_2d(double surface_energy, double young, double poisson, double traction, double domain_factor) {
  const char* what = "2D critical size d*";
  require(surface_energy > 0.0 && std::isfinite(surface_energy), what, "surface energy γ", surface_energy, "> 0");
  require(young > 0.0 && std::isfinite(young), what, "Young's modulus E", young, "> 0");
  require(traction > 0.0 && std::isfinite(traction), what, "traction q", traction, "> 0");
  require(domain_factor > 0.0 && std::isfinite(domain_factor), what, "domain factor 𝓜", domain_factor, "> 0");
  check_poisson(what, poisson);
  return pi * pi * surface_energy * young / ((1.0 - poisson * poisson) * traction * traction * domain_factor);  // (3.23)
}

double separated_ratio_2d(double real_size, double critical_size) { return real_size / critical_size; }  // (3.24)

double combined_ratio_2d(double real_size, double apparent_size, double critical_size) {
  return real_size * real_size / (apparent_size * critical_size);  // (3.26)
}

double contact_fraction(double real_size, double apparent_size) { return real_size / apparent_size; }  // (3.28)

double minimum_contact_fraction(double apparent_size, double critical_size) {
  return std::sqrt(critical_size / apparent_size);  // (3.29)
}

double combined_boundary_2d(double real_size, double critical_size) {
  return real_size * real_size / critical_size;  // (3.27)
}

Region2D classify_2d(double real_size, double apparent_size, double critical_size) {
  check_sizes(real_size, apparent_size, critical_size);
  if (apparent_size < real_size) return Region2D::Inaccessible;                   // d_a ≥ d_r (Fig. 3.7)
  if (real_size < critical_size) return Region2D::Plastic;                        // R_sep < 1 (3.25)
  // R_comb ≥ 1 (3.27), written as d_a ≤ d_r²/d* so that the boundary is the exact line of the map.
  if (apparent_size <= combined_boundary_2d(real_size, critical_size)) return Region2D::Combined;
  return Region2D::Separated;
}

const char* name(Region2D region) {
  switch (region) {
    case Region2D::Inaccessible: return "inaccessible";
    case Region2D::Plastic: return "plastic";
    case Region2D::Separated: return "separated";
    case Region2D::Combined: return "combined";
  }
  return "?";
}

}  // namespace wearscale::wear
