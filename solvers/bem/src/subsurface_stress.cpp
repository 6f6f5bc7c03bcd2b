#include "wearscale/bem/subsurface_stress.hpp"

#include <cmath>

#include <fmt/format.h>

#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

namespace {
using cplx = std::complex<double>;

// σ̂(q, z) of one Fourier mode of the traction (see the header).
ModeStress mode_stress(double qx, double qy, cplx px, cplx py, cplx pz, double depth, double nu) {
  const double q = std::hypot(qx, qy);
  const double c = qx / q, s = qy / q, zeta = q * depth, decay = std::exp(-zeta);
  const cplx i(0.0, 1.0);
  const cplx p = pz, t = c * px + s * py, a = -s * px + c * py;  // P, T, S
  const cplx b = p - i * t;
  const cplx s_ll = (-p + 2.0 * i * t + b * zeta) * decay;  // plane strain in (∥, z)
  const cplx s_zz = -(p + b * zeta) * decay;
  const cplx s_lz = (-t + (t + i * p) * zeta) * decay;
  const cplx s_aa = 2.0 * nu * (-p + i * t) * decay;        // σ_⊥⊥ = ν(σ_∥∥ + σ_zz)
  const cplx s_az = -a * decay;                              // antiplane shear
  const cplx s_la = i * a * decay;
  ModeStress m;
  m.xx = c * c * s_ll + s * s * s_aa - 2.0 * c * s * s_la;
  m.yy = s * s * s_ll + c * c * s_aa + 2.0 * c * s * s_la;
  m.xy = c * s * (s_ll - s_aa) + (c * c - s * s) * s_la;
  m.xz = c * s_lz - s * s_az;
  m.yz = s * s_lz + c * s_az;
  m.zz = s_zz;
  return m;
}
}  // namespace

ModeStress SubsurfaceStress::mode(const Grid2D& g, std::size_t i, std::size_t j, cplx px, cplx py, cplx pz,
                                  double depth, double nu) {
  ModeStress m{};
  if (i == 0 && j == 0) {
    // Uniform traction, no mean lateral strain.
    m.zz = -pz;
    m.xz = -px;
    m.yz = -py;
    m.xx = m.yy = -nu / (1.0 - nu) * pz;
    return m;
  }
  // At Nyquist frequencies (whose sign is ambiguous) keep the part even in q.
  const double qx = g.wavenumber_x(i), qy = g.wavenumber_y(j);
  const bool flip_x = g.nx % 2 == 0 && i == g.nx / 2, flip_y = g.ny % 2 == 0 && j == g.ny / 2;
  int count = 0;
  for (double sx : {1.0, -1.0}) {
    if (sx < 0.0 && !flip_x) continue;
    for (double sy : {1.0, -1.0}) {
      if (sy < 0.0 && !flip_y) continue;
      const ModeStress a = mode_stress(sx * qx, sy * qy, px, py, pz, depth, nu);
      m.xx += a.xx;
      m.yy += a.yy;
      m.zz += a.zz;
      m.xy += a.xy;
      m.xz += a.xz;
      m.yz += a.yz;
      ++count;
    }
  }
  const double w = 1.0 / count;
  m.xx *= w;
  m.yy *= w;
  m.zz *= w;
  m.xy *= w;
  m.xz *= w;
  m.yz *= w;
  return m;
}

SubsurfaceStress::SubsurfaceStress(const Grid2D& grid, double poisson)
    : owned_(std::make_unique<const HalfSpace>(grid, 1.0, poisson, Boundary::Periodic, Response::Normal)),
      body_(owned_.get()) {
  setup();
}

SubsurfaceStress::SubsurfaceStress(const HalfSpace& body) : body_(&body) { setup(); }

void SubsurfaceStress::setup() {
  if (body_->boundary() != Boundary::Periodic)
    throw InputError(fmt::format("subsurface stress: the stresses of a {} half-space are not implemented; allowed: "
                                 "a periodic one",
                                 to_string(body_->boundary())));
  const Grid2D& grid = body_->grid();
  work_ = body_->workspace();
  plan_ = FFTPlanCache::global().plan(grid);
  for (ComplexField* f : {&px_, &py_, &pz_, &sxx_, &syy_, &szz_, &sxy_, &sxz_, &syz_})
    *f = ComplexField::spectrum_of(grid);
}

void SubsurfaceStress::set_traction(const VectorField& p) {
  if (!(p.grid() == grid())) throw std::invalid_argument("SubsurfaceStress::set_traction: grid differs");
  body_->spectrum(p.x, px_, work_);
  body_->spectrum(p.y, py_, work_);
  body_->spectrum(p.z, pz_, work_);
}

void SubsurfaceStress::stress(double depth, StressField& out) {
  if (!(depth >= 0.0) || !std::isfinite(depth))
    throw InputError(fmt::format("subsurface stress: depth {} m is not allowed; allowed: ≥ 0", depth));
  const Grid2D& g = grid();
  if (!(out.grid() == g)) throw std::invalid_argument("SubsurfaceStress::stress: grid differs");
  const double nu = poisson();
  for_each_mode(g, [&](std::size_t i, std::size_t j, std::size_t) {
    const ModeStress m = mode(g, i, j, px_(i, j), py_(i, j), pz_(i, j), depth, nu);
    sxx_(i, j) = m.xx;
    syy_(i, j) = m.yy;
    szz_(i, j) = m.zz;
    sxy_(i, j) = m.xy;
    sxz_(i, j) = m.xz;
    syz_(i, j) = m.yz;
  });
  plan_->backward(sxx_, out.xx);
  plan_->backward(syy_, out.yy);
  plan_->backward(szz_, out.zz);
  plan_->backward(sxy_, out.xy);
  plan_->backward(sxz_, out.xz);
  plan_->backward(syz_, out.yz);
}

}  // namespace wearscale::bem
