#pragma once
// What the normal contact solver asks of the elastic body, on the points this
// process holds: u = K p (the normal block), z = S g (its FFT inverse, the
// preconditioner), Σ t K t, and the sums over all points. One process holds
// the whole grid (HalfSpaceNormal, the serial body) or one slab of rows of it
// (SlabHalfSpace, distributed over MPI ranks with FFTW-MPI): NormalContact is
// one solver over either.
#include <cstddef>
#include <memory>
#include <span>
#include <string_view>
#include <utility>

#include "wearscale/bem/half_space.hpp"
#include "wearscale/bem/two_level_stiffness.hpp"

namespace wearscale::bem {

class NormalOperator {
 public:
  virtual ~NormalOperator() = default;
  /// The whole grid of the contact.
  virtual const Grid2D& grid() const = 0;
  /// The rows held here: rows() × ny points from row first_row() (the fields' grid: local_grid()).
  virtual std::size_t first_row() const = 0;
  virtual const Grid2D& local_grid() const = 0;
  virtual Boundary boundary() const = 0;

  /// u = K (scale · p) on the rows held here.
  virtual void displacement(const RealField& p, RealField& u, double scale) = 0;
  /// z = S g, Ŝ(q) = E*|q|/2 (zero mode: 0).
  virtual void stiffness(const RealField& g, RealField& z) = 0;
  /// z ≈ S g by TwoLevelStiffness (a preconditioner at a quarter of the
  /// transforms) where the body has a 2× coarser grid (periodic, even); S
  /// itself where not (a free window, an odd grid), as this default does.
  virtual void two_level_stiffness(const RealField& g, RealField& z) { stiffness(g, z); }
  /// Σ over every point of the grid of t K t.
  virtual double form(const RealField& t) = 0;
  /// u_z of a cell per unit pressure on it alone [m/Pa]; S at offset 0 [Pa/m].
  virtual double self_compliance() const = 0;
  virtual double stiffness_diagonal() const = 0;

  /// Partial sums of every process → the totals, the same bits on every process
  /// (over ranks: added in rank order, whatever the timing). One process: unchanged.
  virtual void sum(std::span<double> partial) const = 0;
  /// The largest of every process's `local`.
  virtual double max(double local) const = 0;

  /// sum() value by value: sum_each(a, b) replaces a and b by their totals.
  template <class... T>
  void sum_each(T&... values) const {
    double v[] = {static_cast<double>(values)...};
    sum(v);
    std::size_t k = 0;
    ((values = static_cast<T>(v[k++])), ...);
  }
};

/// The scale of a surface held in slabs, the same on every process: its rms
/// height about the mean (1 for a flat one) and its highest point.
struct SurfaceScale {
  double h_rms = 1.0, h_max = 0.0;
};
/// InputError naming `solver` ("normal contact") if any point is NaN or infinite.
SurfaceScale surface_scale(const NormalOperator& body, const RealField& h, std::string_view solver);

/// A whole-grid HalfSpace as the normal part of an operator `Base`
/// (NormalOperator or one deriving from it): one process, sums unchanged.
template <class Base>
class WholeGridBody : public Base {
 public:
  explicit WholeGridBody(HalfSpace body) : body_(std::move(body)), work_(body_.workspace()) {}
  const HalfSpace& half_space() const { return body_; }

  const Grid2D& grid() const override { return body_.grid(); }
  std::size_t first_row() const override { return 0; }
  const Grid2D& local_grid() const override { return body_.grid(); }
  Boundary boundary() const override { return body_.boundary(); }
  void displacement(const RealField& p, RealField& u, double scale) override {
    body_.normal_displacement(p, u, work_, scale);
  }
  void stiffness(const RealField& g, RealField& z) override { body_.normal_stiffness(g, z, work_); }
  void two_level_stiffness(const RealField& g, RealField& z) override {
    if (body_.boundary() != Boundary::Periodic || !TwoLevelStiffness::supports(body_.grid()))
      return stiffness(g, z);
    if (!two_level_) two_level_ = std::make_unique<TwoLevelStiffness>(body_.grid(), body_.contact_modulus());  // once
    two_level_->apply(g, z);
  }
  double form(const RealField& t) override { return body_.normal_form(t, work_); }
  double self_compliance() const override { return body_.self_compliance(); }
  double stiffness_diagonal() const override { return body_.normal_stiffness_diagonal(); }
  void sum(std::span<double>) const override {}
  double max(double local) const override { return local; }

 protected:
  HalfSpace body_;
  HalfSpace::Workspace work_;
  std::unique_ptr<TwoLevelStiffness> two_level_;
};

/// The serial body: a whole-grid HalfSpace's normal block (periodic or free).
class HalfSpaceNormal final : public WholeGridBody<NormalOperator> {
 public:
  HalfSpaceNormal(const Grid2D& grid, double e_star, Boundary boundary)
      : WholeGridBody(HalfSpace::normal(grid, e_star, boundary)) {}
};

}  // namespace wearscale::bem
