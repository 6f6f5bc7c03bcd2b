#include "wearscale/bem/slab_subsurface_stress.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

SlabSubsurfaceStress::SlabSubsurfaceStress(const Grid2D& grid, double poisson, SlabFFT& fft)
    : grid_(grid), local_(grid.slab(fft.rows())), nu_(poisson), fft_(&fft) {
  if (!(poisson > -1.0 && poisson <= 0.5))
    throw InputError(fmt::format("subsurface stress: Poisson's ratio ν = {} is not allowed; allowed: −1 < ν ≤ 0.5",
                                 poisson));
  if (fft.nx() != grid.nx || fft.ny() != grid.ny)
    throw std::invalid_argument("SlabSubsurfaceStress: the transforms are of another grid");
  const std::size_t modes = fft.rows() * grid.spectral_ny();
  for (auto* f : {&px_, &py_, &pz_, &sxx_, &syy_, &szz_, &sxy_, &sxz_, &syz_}) f->assign(modes, {});
}

void SlabSubsurfaceStress::set_traction(const VectorField& p) {
  if (!(p.grid() == local_)) throw std::invalid_argument("SlabSubsurfaceStress: a field that is not this rank's slab");
  for (auto [in, out] : {std::pair{&p.x, &px_}, std::pair{&p.y, &py_}, std::pair{&p.z, &pz_}}) {
    fft_->load(in->data());
    fft_->forward();
    std::copy_n(fft_->spectrum(), out->size(), out->data());
  }
}

void SlabSubsurfaceStress::stress(double depth, StressField& out) {
  if (!(depth >= 0.0) || !std::isfinite(depth))
    throw InputError(fmt::format("subsurface stress: depth {} m is not allowed; allowed: ≥ 0", depth));
  if (!(out.grid() == local_)) throw std::invalid_argument("SlabSubsurfaceStress: a field that is not this rank's slab");
  const std::size_t first = fft_->first_row();
  for_each_mode(local_, [&](std::size_t i, std::size_t j, std::size_t m) {
    const ModeStress s = SubsurfaceStress::mode(grid_, first + i, j, px_[m], py_[m], pz_[m], depth, nu_);
    sxx_[m] = s.xx;
    syy_[m] = s.yy;
    szz_[m] = s.zz;
    sxy_[m] = s.xy;
    sxz_[m] = s.xz;
    syz_[m] = s.yz;
  });
  const double inv_n = 1.0 / static_cast<double>(grid_.size());
  for (auto [in, field] : {std::pair{&sxx_, &out.xx}, std::pair{&syy_, &out.yy}, std::pair{&szz_, &out.zz},
                           std::pair{&sxy_, &out.xy}, std::pair{&sxz_, &out.xz}, std::pair{&syz_, &out.yz}}) {
    std::copy(in->begin(), in->end(), fft_->spectrum());
    fft_->backward();
    fft_->store(field->data(), inv_n);
  }
}

}  // namespace wearscale::bem
