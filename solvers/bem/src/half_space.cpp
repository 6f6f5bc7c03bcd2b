#include "wearscale/bem/half_space.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/bem/spectral_modes.hpp"
#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

namespace {
using cplx = std::complex<double>;
using std::numbers::pi;

void check_material(double e, double nu) {
  if (!(e > 0.0) || !std::isfinite(e))
    throw InputError(fmt::format("elastic half-space: Young's modulus E = {} is not allowed; allowed: E > 0", e));
  if (!(nu > -1.0 && nu <= 0.5))
    throw InputError(fmt::format(
        "elastic half-space: Poisson's ratio ν = {} is not allowed; allowed: −1 < ν ≤ 0.5", nu));
}

// Antiderivatives in x and y of the point solutions, up to terms in x or y
// alone (they cancel in the corner sum of a cell):
//   ∫∫ 1/r = x asinh(y/|x|) + y asinh(x/|y|),   ∫∫ x²/r³ = y asinh(x/|y|),
//   ∫∫ xy/r³ = −r,   ∫∫ x/r² = x atan(y/x) + (y/2) ln(x² + y²).
double x_asinh(double x, double y) { return x == 0.0 ? 0.0 : x * std::asinh(y / std::abs(x)); }
double x_atan(double x, double y) {
  return (x == 0.0 ? 0.0 : x * std::atan(y / x)) + 0.5 * y * std::log(x * x + y * y);
}

// ∫∫ f over the cell [x0, x1] × [y0, y1] from its antiderivative F.
template <class F>
double over_cell(F&& f, double x0, double x1, double y0, double y1) {
  return f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0);
}

struct Cell {
  double x0, x1, y0, y1;
  Cell(double di, double dj, double dx, double dy)
      : x0((di - 0.5) * dx), x1((di + 0.5) * dx), y0((dj - 0.5) * dy), y1((dj + 0.5) * dy) {}
};

// The blocks of the cell response, each on its own (the free kernel builds one at a time).
double cell_zz(const Cell& c, double g, double nu) {  // Boussinesq (2.35c) over the cell: Love (1929)
  return (1.0 - nu) / (2.0 * pi * g) *
         over_cell([](double x, double y) { return x_asinh(x, y) + x_asinh(y, x); }, c.x0, c.x1, c.y0, c.y1);
}
double cell_xx(const Cell& c, double g, double nu) {  // Cerruti, in-line (4.3)
  auto f = [&](double x, double y) { return 2.0 * (1.0 - nu) * x_asinh(x, y) + 2.0 * x_asinh(y, x); };
  return over_cell(f, c.x0, c.x1, c.y0, c.y1) / (4.0 * pi * g);
}
double cell_yy(const Cell& c, double g, double nu) {
  auto f = [&](double x, double y) { return 2.0 * (1.0 - nu) * x_asinh(y, x) + 2.0 * x_asinh(x, y); };
  return over_cell(f, c.x0, c.x1, c.y0, c.y1) / (4.0 * pi * g);
}
double cell_xy(const Cell& c, double g, double nu) {  // ν xy/(2πG r³)
  return nu / (2.0 * pi * g) * over_cell([](double x, double y) { return -std::hypot(x, y); }, c.x0, c.x1, c.y0, c.y1);
}
double cell_xz(const Cell& c, double g, double nu) {  // u_x from p_z: −(1−2ν) x/(4πG r²) (2.35a)
  return -(1.0 - 2.0 * nu) / (4.0 * pi * g) * over_cell(x_atan, c.x0, c.x1, c.y0, c.y1);
}
double cell_yz(const Cell& c, double g, double nu) {
  return -(1.0 - 2.0 * nu) / (4.0 * pi * g) *
         over_cell([](double x, double y) { return x_atan(y, x); }, c.x0, c.x1, c.y0, c.y1);
}
}  // namespace

double HalfSpace::normal_mode(const Grid2D& g, std::size_t i, std::size_t j, double e_star) {
  const double s = 2.0 / (e_star * static_cast<double>(g.size()));  // (2.39), 1/N folded in
  const double qx = g.wavenumber_x(i), qy = g.wavenumber_y(j);
  const double q = std::sqrt(qx * qx + qy * qy);
  return q > 0.0 ? s / q : 0.0;
}

double HalfSpace::stiffness_mode(const Grid2D& g, std::size_t i, std::size_t j, double e_star) {
  const double scale = 0.5 * e_star / static_cast<double>(g.size());
  return scale * std::hypot(g.wavenumber_x(i), g.wavenumber_y(j));
}

const char* to_string(Boundary b) { return b == Boundary::Periodic ? "periodic" : "free"; }

HalfSpace::HalfSpace(const Grid2D& grid, double young, double poisson, Boundary boundary, Response response)
    : HalfSpace(grid, young, poisson, young / (2.0 * (1.0 + poisson)), boundary, response, 0.0) {}

HalfSpace HalfSpace::normal(const Grid2D& grid, double e_star, Boundary boundary) {
  return HalfSpace(grid, e_star, 0.0, 0.5 * e_star, boundary, Response::Normal, e_star);
}

HalfSpace HalfSpace::from_shear_modulus(const Grid2D& grid, double shear_modulus, double poisson, Boundary boundary,
                                        Response response) {
  return HalfSpace(grid, 2.0 * shear_modulus * (1.0 + poisson), poisson, shear_modulus, boundary, response, 0.0);
}

HalfSpace::HalfSpace(const Grid2D& grid, double young, double poisson, double shear, Boundary boundary,
                     Response response, double e_star_normal)
    : grid_(grid), young_(young), poisson_(poisson), shear_(shear), boundary_(boundary), response_(response) {
  check_material(young, poisson);  // G > 0 follows (or, from_shear_modulus, E > 0 from G > 0)
  if (grid.nx < 2 || grid.ny < 2 || !(grid.lx > 0) || !(grid.ly > 0))
    throw InputError(fmt::format("elastic half-space: grid {} is not allowed; allowed: ≥ 2×2 points, sizes > 0",
                                 grid.to_string()));
  fft_grid_ = boundary == Boundary::Periodic ? grid : Grid2D(2 * grid.nx, 2 * grid.ny, 2 * grid.lx, 2 * grid.ly);
  plan_ = FFTPlanCache::global().plan(fft_grid_);
  const std::size_t modes = fft_grid_.spectral_size();
  if (keeps(Response::Normal)) zz_.assign(modes, 0.0);
  if (keeps(Response::ShearX)) xx_.assign(modes, 0.0);
  if (response == Response::Full)
    for (auto* f : {&yy_, &xy_, &xz_, &yz_}) f->assign(modes, 0.0);
  if (boundary == Boundary::Periodic)
    build_periodic_kernel(e_star_normal);
  else
    build_free_kernel();
  // The displacement of a cell under a unit pressure on itself: the kernel at
  // offset 0, i.e. Σ_q F_zz(q) over the whole spectrum (1/N folded in).
  if (keeps(Response::Normal)) {
    self_compliance_ = hermitian_sum<double>(fft_grid_, [&](std::size_t m, double w, double& s) { s += w * zz_[m]; });
    stiffness_.assign(modes, 0.0);
    const double e_star = e_star_normal > 0.0 ? e_star_normal : contact_modulus();
    const Grid2D& f = fft_grid_;
    for_each_mode(f, [&](std::size_t i, std::size_t j, std::size_t m) { stiffness_[m] = stiffness_mode(f, i, j, e_star); });
    stiffness_diagonal_ =
        hermitian_sum<double>(fft_grid_, [&](std::size_t m, double w, double& s) { s += w * stiffness_[m]; });
  }
  own_ = workspace();
}

void HalfSpace::build_periodic_kernel(double e_star_normal) {
  const Grid2D& g = grid_;
  if (response_ == Response::Normal) {  // (2.39) with E*, 1/N folded in
    const double e_star = e_star_normal > 0.0 ? e_star_normal : contact_modulus();
    for_each_mode(g, [&](std::size_t i, std::size_t j, std::size_t m) { zz_[m] = normal_mode(g, i, j, e_star); });
    return;
  }
  for_each_mode(g, [&](std::size_t i, std::size_t j, std::size_t m) {
    const TensorMode f = tensor_mode(g, i, j, shear_, poisson_);
    xx_[m] = f.xx;
    if (response_ == Response::ShearX) return;
    yy_[m] = f.yy;
    xy_[m] = f.xy;
    zz_[m] = f.zz;
    xz_[m] = f.xz;
    yz_[m] = f.yz;
  });
}

HalfSpace::TensorMode HalfSpace::tensor_mode(const Grid2D& g, std::size_t i, std::size_t j, double shear,
                                             double poisson) {
  const double inv_n = 1.0 / static_cast<double>(g.size());
  const bool nyq_x = g.nx % 2 == 0, nyq_y = g.ny % 2 == 0;
  // The odd coupling dropped at Nyquist frequencies (their sign is ambiguous).
  const GreenTensor f = green_tensor(g.wavenumber_x(i), g.wavenumber_y(j), shear, poisson, !(nyq_x && i == g.nx / 2),
                                     !(nyq_y && j == g.ny / 2));
  TensorMode t;
  t.xx = f[0][0].real() * inv_n;
  t.yy = f[1][1].real() * inv_n;
  t.xy = f[0][1].real() * inv_n;
  t.zz = f[2][2].real() * inv_n;
  t.xz = f[0][2].imag() * inv_n;
  t.yz = f[1][2].imag() * inv_n;
  return t;
}

void HalfSpace::build_free_kernel() {
  // Each block: its cell responses at offsets −(n−1)..(n−1) placed periodically
  // on the padded grid (offset n stays 0, so the parity in x and y is exact),
  // then one r2c. Even blocks have a real spectrum, odd ones an imaginary one.
  const Grid2D& p = fft_grid_;
  const long nx = static_cast<long>(grid_.nx), ny = static_cast<long>(grid_.ny);
  const double dx = grid_.dx(), dy = grid_.dy(), g = shear_, nu = poisson_, inv_n = 1.0 / static_cast<double>(p.size());
  RealField k(p);
  ComplexField s = ComplexField::spectrum_of(p);
  auto build = [&](std::vector<double>& out, double (*cell)(const Cell&, double, double), int parity_x, int parity_y,
                   bool imaginary) {
    k.fill(0.0);
#pragma omp parallel for schedule(dynamic, 16)
    for (long a = 0; a < nx; ++a)
      for (long b = 0; b < ny; ++b) {
        const double v = cell(Cell(static_cast<double>(a), static_cast<double>(b), dx, dy), g, nu);
        for (const long sx : {1L, -1L}) {
          if (sx < 0 && a == 0) continue;
          for (const long sy : {1L, -1L}) {
            if (sy < 0 && b == 0) continue;
            const double sign = (sx < 0 ? parity_x : 1) * (sy < 0 ? parity_y : 1);
            k[p.periodic_index(sx * a, sy * b)] = sign * v;
          }
        }
      }
    plan_->forward(k, s);
    for (std::size_t m = 0; m < out.size(); ++m) out[m] = (imaginary ? s[m].imag() : s[m].real()) * inv_n;
  };
  if (keeps(Response::Normal)) build(zz_, cell_zz, 1, 1, false);
  if (keeps(Response::ShearX)) build(xx_, cell_xx, 1, 1, false);
  if (response_ != Response::Full) return;
  build(yy_, cell_yy, 1, 1, false);
  build(xy_, cell_xy, -1, -1, false);
  build(xz_, cell_xz, -1, 1, true);
  build(yz_, cell_yz, 1, -1, true);
}

double HalfSpace::cell_response(Block block, double di, double dj, double dx, double dy, double g, double nu) {
  const Cell c(di, dj, dx, dy);
  switch (block) {
    case Block::xx: return cell_xx(c, g, nu);
    case Block::yy: return cell_yy(c, g, nu);
    case Block::xy: return cell_xy(c, g, nu);
    case Block::zz: return cell_zz(c, g, nu);
    case Block::xz: return cell_xz(c, g, nu);
    case Block::yz: return cell_yz(c, g, nu);
  }
  return 0.0;
}

HalfSpace::Workspace HalfSpace::workspace() const {
  Workspace w;
  if (boundary_ == Boundary::Free) w.padded = RealField(fft_grid_);
  if (keeps(Response::ShearX)) w.sx = ComplexField::spectrum_of(fft_grid_);
  if (response_ == Response::Full) w.sy = ComplexField::spectrum_of(fft_grid_);
  if (keeps(Response::Normal)) w.sz = ComplexField::spectrum_of(fft_grid_);
  return w;
}

GreenTensor HalfSpace::green_tensor(double qx, double qy, double g, double nu, bool odd_x, bool odd_y) {
  GreenTensor f{};
  const double q2 = qx * qx + qy * qy;
  if (q2 == 0.0) return f;
  const double q = std::sqrt(q2);
  const double s = 1.0 / (g * q);
  const double c = 0.5 * (1.0 - 2.0 * nu) / q;  // coupling (4.22), odd in q
  const cplx xz(0.0, odd_x ? s * c * qx : 0.0), yz(0.0, odd_y ? s * c * qy : 0.0);
  f[0][0] = s * (1.0 - nu * qx * qx / q2);  // Cerruti, in-line (4.3)
  f[1][1] = s * (1.0 - nu * qy * qy / q2);
  f[0][1] = f[1][0] = -s * nu * qx * qy / q2;
  f[0][2] = xz;  // u_x from p_z (2.35a)
  f[1][2] = yz;
  f[2][0] = std::conj(xz);  // u_z from p_x = −u_x from p_z reflected (4.22)
  f[2][1] = std::conj(yz);
  f[2][2] = s * (1.0 - nu);  // Boussinesq (2.35c)
  return f;
}

void HalfSpace::forward(const RealField& in, ComplexField& out, Workspace& w) const {
  if (!(in.grid() == grid_)) throw std::invalid_argument("HalfSpace: a field on another grid");
  if (boundary_ == Boundary::Periodic) {
    plan_->forward(in, out);
    return;
  }
  RealField& p = w.padded;
  p.fill(0.0);
  const std::size_t nx = grid_.nx, ny = grid_.ny;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j) p(i, j) = in(i, j);
  plan_->forward(p, out);
}

void HalfSpace::backward(ComplexField& in, RealField& out, Workspace& w) const {
  if (boundary_ == Boundary::Periodic) {
    plan_->backward_unnormalized(in, out);
    return;
  }
  RealField& p = w.padded;
  plan_->backward_unnormalized(in, p);
  const std::size_t nx = grid_.nx, ny = grid_.ny;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j) out(i, j) = p(i, j);
}

void HalfSpace::displacement(const VectorField& p, VectorField& u, Workspace& w) const {
  if (response_ != Response::Full) throw std::logic_error("HalfSpace::displacement needs the full response");
  forward(p.x, w.sx, w);
  forward(p.y, w.sy, w);
  forward(p.z, w.sz, w);
  // û = F p̂ (A.4) in real arithmetic (std::complex products call __muldc3).
  double* a = reinterpret_cast<double*>(w.sx.data());
  double* b = reinterpret_cast<double*>(w.sy.data());
  double* c = reinterpret_cast<double*>(w.sz.data());
  const std::size_t modes = zz_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t m = 0; m < modes; ++m)
    apply_mode({xx_[m], yy_[m], xy_[m], zz_[m], xz_[m], yz_[m]}, a + 2 * m, b + 2 * m, c + 2 * m);
  backward(w.sx, u.x, w);
  backward(w.sy, u.y, w);
  backward(w.sz, u.z, w);
}

void HalfSpace::normal_displacement(const RealField& p, RealField& u, Workspace& w, double scale) const {
  if (!keeps(Response::Normal)) throw std::logic_error("HalfSpace::normal_displacement needs the normal response");
  forward(p, w.sz, w);
  multiply_modes(w.sz.values(), zz_, scale);
  backward(w.sz, u, w);
}

void HalfSpace::normal_stiffness(const RealField& g, RealField& p, Workspace& w) const {
  if (!keeps(Response::Normal)) throw std::logic_error("HalfSpace::normal_stiffness needs the normal response");
  forward(g, w.sz, w);
  multiply_modes(w.sz.values(), stiffness_);
  backward(w.sz, p, w);
}

void HalfSpace::shear_displacement(const RealField& p, RealField& u, Workspace& w) const {
  if (!keeps(Response::ShearX)) throw std::logic_error("HalfSpace::shear_displacement needs the shear response");
  forward(p, w.sx, w);
  multiply_modes(w.sx.values(), xx_);
  backward(w.sx, u, w);
}

double HalfSpace::normal_form(const RealField& t, Workspace& w) const {
  if (!keeps(Response::Normal)) throw std::logic_error("HalfSpace::normal_form needs the normal response");
  forward(t, w.sz, w);
  const auto* s = w.sz.data();
  const double* k = zz_.data();
  // Σ_x t (F t) = (1/N) Σ_q F(q) |t̂(q)|², the 1/N being in the kernel.
  return hermitian_sum<double>(fft_grid_, [&](std::size_t m, double wt, double& sum) { sum += wt * k[m] * std::norm(s[m]); });
}

HalfSpace::BlockForm HalfSpace::form(const VectorField& t, Workspace& w) const {
  if (response_ != Response::Full) throw std::logic_error("HalfSpace::form needs the full response");
  forward(t.x, w.sx, w);
  forward(t.y, w.sy, w);
  forward(t.z, w.sz, w);
  const double* a = reinterpret_cast<const double*>(w.sx.data());
  const double* b = reinterpret_cast<const double*>(w.sy.data());
  const double* c = reinterpret_cast<const double*>(w.sz.data());
  return hermitian_sum<BlockForm>(fft_grid_, [&](std::size_t m, double wt, BlockForm& f) {
    add_form_mode({xx_[m], yy_[m], xy_[m], zz_[m], xz_[m], yz_[m]}, wt, a + 2 * m, b + 2 * m, c + 2 * m, f);
  });
}

double HalfSpace::elastic_energy(const VectorField& p, const VectorField& u) {
  return elastic_energy(p.x, u.x) + elastic_energy(p.y, u.y) + elastic_energy(p.z, u.z);
}

double HalfSpace::elastic_energy(const RealField& p, const RealField& u) {
  double sum = 0.0;
  const std::size_t n = p.size();
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (std::size_t k = 0; k < n; ++k) sum += p[k] * u[k];
  return 0.5 * sum * p.grid().cell_area();
}

}  // namespace wearscale::bem
