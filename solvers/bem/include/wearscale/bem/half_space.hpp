#pragma once
// The elastic half-space: surface tractions → surface displacements through
// the Boussinesq–Cerruti Green's tensor (§2.3.1). The one operator every BEM
// solver applies (normal and frictional contact, the stresses' spectra, the
// wear maps' energies).
//
// Conventions: z points into the solid; p_z > 0 is compressive and u_z > 0
// moves the surface into the solid. The forward FFT is e^{-iq·x}; with the
// unnormalised DFT p̂, û(q) = F(q) p̂(q) and u = IDFT(û).
//
// Two boundaries:
//  - Periodic: the grid is one cell of a periodic surface and u = F * p the
//    periodic convolution (A.4), F(q) the tensor (2.35), (4.3), (4.22) at each
//    mode. F(0) = 0: a mean traction gives no mean displacement (in a periodic
//    half-space the mean displacement is undefined; contact solvers fix it by
//    their constraint).
//  - Free: the grid is a window on an unbounded half-space loaded only inside
//    it. The kernel is the exact displacement caused by a traction uniform over
//    one cell (Love 1929 for the normal block; Cerruti's point solutions
//    integrated over the cell likewise for the others), and u = F * p the
//    linear convolution, by FFT on a zero-padded 2nx × 2ny grid (DC-FFT). u is
//    the true displacement, vanishing far away (its mean is not zero).
#include <array>
#include <complex>
#include <memory>
#include <vector>

#include "wearscale/core/fft.hpp"

namespace wearscale::bem {

/// Three components of a surface traction or displacement field.
struct VectorField {
  RealField x, y, z;
  explicit VectorField(const Grid2D& g) : x(g), y(g), z(g) {}
  const Grid2D& grid() const { return z.grid(); }
};

using GreenTensor = std::array<std::array<std::complex<double>, 3>, 3>;

enum class Boundary { Periodic, Free };
const char* to_string(Boundary b);

/// The blocks of the tensor a HalfSpace keeps (each costs one half spectrum).
enum class Response {
  Normal,  ///< u_z from p_z (Boussinesq)
  ShearX,  ///< u_x from p_x (Cerruti, in-line)
  Full,    ///< all nine, coupling (4.22) included
};

/// A block ij of the tensor: u_i from p_j (the others follow by Betti:
/// F_yx = F_xy, F_zx = conj(F_xz), F_zy = conj(F_yz)).
enum class Block { xx, yy, xy, zz, xz, yz };

class HalfSpace {
 public:
  /// Scratch of one application (one per thread that applies the operator at once).
  struct Workspace {
    RealField padded;          // the zero-padded field (free boundary only)
    ComplexField sx, sy, sz;   // spectra of the components the response needs
  };
  /// Σ_x t·(F t) split into its normal (nn), tangential (tt) and coupling (nt, counted once) blocks.
  struct BlockForm {
    double nn = 0.0, tt = 0.0, nt = 0.0;
    BlockForm& operator+=(const BlockForm& o) {
      nn += o.nn, tt += o.tt, nt += o.nt;
      return *this;
    }
  };

  /// InputError unless E > 0 and −1 < ν ≤ 0.5 (ν = 0.5: incompressible, normal and tangential decoupled).
  HalfSpace(const Grid2D& grid, double young, double poisson, Boundary boundary = Boundary::Periodic,
            Response response = Response::Full);
  /// The normal block of a rigid body pressed on an elastic one, from the contact modulus (1.12):
  /// F_zz(q) = 2/(E* q). (young() = E*, poisson() = 0.)
  static HalfSpace normal(const Grid2D& grid, double e_star, Boundary boundary = Boundary::Periodic);
  /// The same as the constructor, from the shear modulus G instead of E.
  static HalfSpace from_shear_modulus(const Grid2D& grid, double shear_modulus, double poisson, Boundary boundary,
                                      Response response);

  /// The grid of the tractions and displacements.
  const Grid2D& grid() const { return grid_; }
  /// The grid the FFTs run on: grid() (periodic) or its 2nx × 2ny padding (free).
  const Grid2D& fft_grid() const { return fft_grid_; }
  Boundary boundary() const { return boundary_; }
  Response response() const { return response_; }
  double young() const { return young_; }
  double poisson() const { return poisson_; }
  double shear_modulus() const { return shear_; }
  /// E/(1−ν²): the E* of this body against a rigid one (1.12).
  double contact_modulus() const { return young_ / (1.0 - poisson_ * poisson_); }
  /// u_z at a cell per unit p_z on that cell alone [m/Pa].
  double self_compliance() const { return self_compliance_; }

  /// Scratch for the const applications below.
  Workspace workspace() const;

  /// u = F * p, all components (Full): 3 r2c + 3 c2r.
  void displacement(const VectorField& traction, VectorField& u, Workspace& w) const;
  /// u_z = F_zz * (scale · p_z) (Normal or Full): one r2c + one c2r.
  void normal_displacement(const RealField& p, RealField& u, Workspace& w, double scale = 1.0) const;
  /// u_x = F_xx * p_x (ShearX or Full): one r2c + one c2r.
  void shear_displacement(const RealField& p, RealField& u, Workspace& w) const;
  /// p = S * g with Ŝ(q) = E* |q| / 2, the inverse of the normal block of a
  /// periodic body (but for the zero mode, mapped to 0): the FFT-based
  /// preconditioner of the contact solvers (Vollebregt 2014). One r2c + one c2r.
  void normal_stiffness(const RealField& g, RealField& p, Workspace& w) const;
  /// S at offset 0: the pressure on a cell per unit displacement of that cell alone under S [Pa/m].
  double normal_stiffness_diagonal() const { return stiffness_diagonal_; }
  /// Σ_x t (F_zz t) by Parseval from the spectrum of t: one r2c.
  double normal_form(const RealField& t, Workspace& w) const;
  /// The blocks of Σ_x t·(F t) by Parseval (Full): three r2c.
  BlockForm form(const VectorField& t, Workspace& w) const;

  /// The r2c of one traction component on fft_grid() (through the padding if free).
  void spectrum(const RealField& traction, ComplexField& out, Workspace& w) const { forward(traction, out, w); }

  /// The same with the body's own workspace: one HalfSpace must then not be
  /// used by two threads at once.
  void displacement(const VectorField& traction, VectorField& u) { displacement(traction, u, own_); }
  void normal_displacement(const RealField& p, RealField& u) { normal_displacement(p, u, own_); }

  /// F_ij(q): û_i = F_ij p̂_j, from (2.35), (4.3) and (4.22) (Betti-symmetric:
  /// F_zx = conj(F_xz)). Zero at q = 0. `odd_x`/`odd_y` = false drop the odd
  /// (imaginary) coupling along that axis, as done at Nyquist frequencies.
  static GreenTensor green_tensor(double qx, double qy, double shear_modulus, double poisson, bool odd_x = true,
                                  bool odd_y = true);
  /// Block ij of the free half-space's response [m/Pa]: u_i at offset (di, dj)
  /// cells caused by a unit p_j uniform over one dx × dy cell, the point
  /// solutions (2.35), (4.3) integrated exactly over the cell (Love's
  /// rectangle for zz).
  static double cell_response(Block block, double di, double dj, double dx, double dy, double shear_modulus,
                              double poisson);

  /// The periodic normal block of a rigid body on an elastic one at r2c mode
  /// (i, j) of `g`, 1/N folded in: 2/(E* q N) (0 at q = 0); and its inverse,
  /// the preconditioner E* q/(2N). Every body that holds these modes (whole or
  /// in slabs) takes them from here.
  static double normal_mode(const Grid2D& g, std::size_t i, std::size_t j, double e_star);
  static double stiffness_mode(const Grid2D& g, std::size_t i, std::size_t j, double e_star);

  /// The periodic tensor (all blocks) at r2c mode (i, j) of `g`, 1/N folded in,
  /// as kept: F = [[xx, xy, i xz], [xy, yy, i yz], [−i xz, −i yz, zz]], the odd
  /// coupling dropped at Nyquist rows and columns. Every body that holds these
  /// modes (whole or in slabs) takes them from here.
  struct TensorMode {
    double xx = 0.0, yy = 0.0, xy = 0.0, zz = 0.0, xz = 0.0, yz = 0.0;
  };
  static TensorMode tensor_mode(const Grid2D& g, std::size_t i, std::size_t j, double shear_modulus, double poisson);
  /// û = F p̂ at one mode, in place: a, b, c the (re, im) of the x, y, z spectra there.
  static void apply_mode(const TensorMode& f, double* a, double* b, double* c) {
    const double xr = a[0], xi = a[1], yr = b[0], yi = b[1], zr = c[0], zi = c[1];
    a[0] = f.xx * xr + f.xy * yr - f.xz * zi;  // i g z = (−g z_i, g z_r)
    a[1] = f.xx * xi + f.xy * yi + f.xz * zr;
    b[0] = f.xy * xr + f.yy * yr - f.yz * zi;
    b[1] = f.xy * xi + f.yy * yi + f.yz * zr;
    c[0] = f.xz * xi + f.yz * yi + f.zz * zr;  // −i g x = (g x_i, −g x_r)
    c[1] = -f.xz * xr - f.yz * yr + f.zz * zi;
  }
  /// Adds weight × the blocks of t̂ᴴ F t̂ at one mode (F Hermitian: each is real) to `form`.
  static void add_form_mode(const TensorMode& f, double weight, const double* a, const double* b, const double* c,
                            BlockForm& form) {
    const double xr = a[0], xi = a[1], yr = b[0], yi = b[1], zr = c[0], zi = c[1];
    // Im(conj(x) z) = x_r z_i − x_i z_r.
    form.nn += weight * f.zz * (zr * zr + zi * zi);
    form.tt += weight * (f.xx * (xr * xr + xi * xi) + f.yy * (yr * yr + yi * yi) + 2.0 * f.xy * (xr * yr + xi * yi));
    form.nt -= weight * (f.xz * (xr * zi - xi * zr) + f.yz * (yr * zi - yi * zr));
  }

  /// E_el = ½ ∫ p·u dA   (4.1)
  static double elastic_energy(const VectorField& traction, const VectorField& u);
  static double elastic_energy(const RealField& p, const RealField& u);

 private:
  HalfSpace(const Grid2D& grid, double young, double poisson, double shear, Boundary boundary, Response response,
            double e_star_normal);
  void build_periodic_kernel(double e_star_normal);
  void build_free_kernel();
  // The r2c of a traction component into `out` (through the padding if free).
  void forward(const RealField& in, ComplexField& out, Workspace& w) const;
  // The c2r of a displacement spectrum into `out` (cropping the padding if free); `in` is overwritten.
  void backward(ComplexField& in, RealField& out, Workspace& w) const;
  bool keeps(Response r) const { return response_ == Response::Full || response_ == r; }

  Grid2D grid_, fft_grid_;
  double young_, poisson_, shear_;
  Boundary boundary_;
  Response response_;
  std::shared_ptr<const FFTPlan> plan_;
  // The tensor on the half spectrum of fft_grid_, 1/N of the inverse folded in:
  // F = [[xx, xy, i xz], [xy, yy, i yz], [−i xz, −i yz, zz]]; empty blocks are not kept.
  std::vector<double> xx_, yy_, xy_, zz_, xz_, yz_;
  std::vector<double> stiffness_;  // E* |q| / 2 on the same half spectrum, 1/N folded in
  double self_compliance_ = 0.0, stiffness_diagonal_ = 0.0;
  Workspace own_;
};

}  // namespace wearscale::bem
