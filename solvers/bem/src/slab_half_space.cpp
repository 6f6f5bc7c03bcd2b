#include "wearscale/bem/slab_half_space.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/mpi.hpp"

namespace wearscale::bem {

const Grid2D& checked_slab_grid(const Grid2D& g, double e_star, const char* body) {
  if (!(e_star > 0.0) || !std::isfinite(e_star))
    throw InputError(fmt::format("{}: E* = {} is not allowed; allowed: E* > 0", body, e_star));
  if (g.nx < 2 || g.ny < 2 || !(g.lx > 0.0) || !(g.ly > 0.0))
    throw InputError(fmt::format("{}: grid {} is not allowed; allowed: ≥ 2×2 points, sizes > 0", body, g.to_string()));
  return g;
}

namespace {
const Grid2D& checked(const Grid2D& g, double e_star) { return checked_slab_grid(g, e_star, "distributed half-space"); }
}  // namespace

SlabHalfSpace::SlabHalfSpace(const Grid2D& grid, double e_star, PlanRigor rigor)
    : grid_(checked(grid, e_star)), fft_(grid.nx, grid.ny, rigor), e_star_(e_star), rigor_(rigor) {
  local_ = grid_.slab(fft_.rows());
  const std::size_t cols = grid_.spectral_ny(), first = fft_.first_row();
  zz_.assign(fft_.rows() * cols, 0.0);
  stiffness_.assign(fft_.rows() * cols, 0.0);
  for_each_mode(grid_.slab(fft_.rows()), [&](std::size_t i, std::size_t j, std::size_t m) {
    zz_[m] = HalfSpace::normal_mode(grid_, first + i, j, e_star);
    stiffness_[m] = HalfSpace::stiffness_mode(grid_, first + i, j, e_star);
  });
  self_compliance_ = whole_spectrum_sum(zz_);
  stiffness_diagonal_ = whole_spectrum_sum(stiffness_);
}

SlabHalfSpace::SlabHalfSpace(const Grid2D& grid, double young, double poisson, PlanRigor rigor)
    : grid_(checked(grid, young)), fft_(grid.nx, grid.ny, rigor), rigor_(rigor) {
  if (!(poisson > -1.0 && poisson <= 0.5))
    throw InputError(fmt::format(
        "distributed half-space: Poisson's ratio ν = {} is not allowed; allowed: −1 < ν ≤ 0.5", poisson));
  young_ = young;
  poisson_ = poisson;
  local_ = grid_.slab(fft_.rows());
  const std::size_t cols = grid_.spectral_ny(), first = fft_.first_row(), modes = fft_.rows() * cols;
  const double shear = young / (2.0 * (1.0 + poisson)), e_star = young / (1.0 - poisson * poisson);
  e_star_ = e_star;
  tensor_.assign(modes, {});
  zz_.assign(modes, 0.0);
  stiffness_.assign(modes, 0.0);
  for_each_mode(local_, [&](std::size_t i, std::size_t j, std::size_t m) {
    tensor_[m] = HalfSpace::tensor_mode(grid_, first + i, j, shear, poisson);
    zz_[m] = tensor_[m].zz;
    stiffness_[m] = HalfSpace::stiffness_mode(grid_, first + i, j, e_star);
  });
  for (auto* s : {&sx_, &sy_, &sz_}) s->assign(modes, {});
  self_compliance_ = whole_spectrum_sum(zz_);
  stiffness_diagonal_ = whole_spectrum_sum(stiffness_);
}

// Σ over the whole spectrum of a kernel known on this rank's rows of the half spectrum.
double SlabHalfSpace::whole_spectrum_sum(const std::vector<double>& kernel) const {
  double s = hermitian_sum<double>(local_, [&](std::size_t m, double w, double& t) { t += w * kernel[m]; });
  return mpi::sum(s);
}

void SlabHalfSpace::apply(const RealField& in, RealField& out, const std::vector<double>& kernel, double scale) {
  if (!(in.grid() == local_) || !(out.grid() == local_))
    throw std::invalid_argument("SlabHalfSpace: a field that is not this rank's slab");
  fft_.load(in.data());
  fft_.forward();
  multiply_modes({fft_.spectrum(), kernel.size()}, kernel, scale);
  fft_.backward();
  fft_.store(out.data());
}

void SlabHalfSpace::displacement(const RealField& p, RealField& u, double scale) { apply(p, u, zz_, scale); }
void SlabHalfSpace::stiffness(const RealField& g, RealField& z) { apply(g, z, stiffness_, 1.0); }

void SlabHalfSpace::two_level_stiffness(const RealField& g, RealField& z) {
  if (!TwoLevelStiffness::supports(grid_)) return stiffness(g, z);
  if (!(g.grid() == local_) || !(z.grid() == local_))
    throw std::invalid_argument("SlabHalfSpace: a field that is not this rank's slab");
  if (!two_level_)
    two_level_ = std::make_unique<SlabTwoLevelStiffness>(grid_, RowRange{fft_.first_row(), fft_.rows()}, e_star_, rigor_);
  two_level_->apply(g.data(), z.data());
}

double SlabHalfSpace::form(const RealField& t) {
  if (!(t.grid() == local_)) throw std::invalid_argument("SlabHalfSpace: a field that is not this rank's slab");
  fft_.load(t.data());
  fft_.forward();
  const auto* s = fft_.spectrum();
  const double* k = zz_.data();
  // Σ_x t (F t) = (1/N) Σ_q F(q) |t̂(q)|², the 1/N being in the kernel.
  const double local =
      hermitian_sum<double>(local_, [&](std::size_t m, double w, double& sum) { sum += w * k[m] * std::norm(s[m]); });
  return mpi::sum(local);
}

void SlabHalfSpace::spectra_of(const VectorField& t) {
  if (tensor_.empty()) throw std::logic_error("SlabHalfSpace: the full tensor needs the (E, ν) constructor");
  if (!(t.grid() == local_)) throw std::invalid_argument("SlabHalfSpace: a field that is not this rank's slab");
  const std::size_t n = sx_.size();
  for (auto [in, out] : {std::pair{&t.x, &sx_}, std::pair{&t.y, &sy_}, std::pair{&t.z, &sz_}}) {
    fft_.load(in->data());
    fft_.forward();
    std::copy(fft_.spectrum(), fft_.spectrum() + n, out->data());
  }
}

void SlabHalfSpace::vector_displacement(const VectorField& p, VectorField& u) {
  if (!(u.grid() == local_)) throw std::invalid_argument("SlabHalfSpace: a field that is not this rank's slab");
  spectra_of(p);
  // û = F p̂ (A.4), the same modes and arithmetic as HalfSpace::displacement.
  double* a = reinterpret_cast<double*>(sx_.data());
  double* b = reinterpret_cast<double*>(sy_.data());
  double* c = reinterpret_cast<double*>(sz_.data());
  const HalfSpace::TensorMode* f = tensor_.data();
  const std::size_t modes = tensor_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t m = 0; m < modes; ++m) HalfSpace::apply_mode(f[m], a + 2 * m, b + 2 * m, c + 2 * m);
  for (auto [in, out] : {std::pair{&sx_, &u.x}, std::pair{&sy_, &u.y}, std::pair{&sz_, &u.z}}) {
    std::copy(in->begin(), in->end(), fft_.spectrum());
    fft_.backward();
    fft_.store(out->data());
  }
}

HalfSpace::BlockForm SlabHalfSpace::block_form(const VectorField& t) {
  spectra_of(t);
  const double* a = reinterpret_cast<const double*>(sx_.data());
  const double* b = reinterpret_cast<const double*>(sy_.data());
  const double* c = reinterpret_cast<const double*>(sz_.data());
  const HalfSpace::TensorMode* f = tensor_.data();
  const HalfSpace::BlockForm local = hermitian_sum<HalfSpace::BlockForm>(
      local_, [&](std::size_t m, double w, HalfSpace::BlockForm& sum) {
        HalfSpace::add_form_mode(f[m], w, a + 2 * m, b + 2 * m, c + 2 * m, sum);
      });
  double parts[] = {local.nn, local.tt, local.nt};
  mpi::sum(std::span<double>(parts));
  return {parts[0], parts[1], parts[2]};
}

void SlabHalfSpace::sum(std::span<double> partial) const { mpi::sum(partial); }
double SlabHalfSpace::max(double local) const { return mpi::max(local); }

}  // namespace wearscale::bem
