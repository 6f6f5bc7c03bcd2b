#pragma once
// A real-to-complex FFT pair of an nx × ny grid distributed in slabs over the
// ranks of the job (FFTW-MPI, MPI_COMM_WORLD): rank r holds the rows
// [first_row, first_row + rows) of the real field and the same rows of its
// r2c spectrum (FFTW's block distribution along x, not transposed). The plans
// are made once, collectively, and run on the object's own buffers, so an
// application allocates nothing. Needs a build with WEARSCALE_MPI and an
// active mpi::Session (under mpirun, also at P = 1).
#include <complex>
#include <cstddef>

#include "wearscale/core/fft.hpp"
#include "wearscale/core/grid.hpp"
#include "wearscale/core/row_exchange.hpp"

namespace wearscale {

class SlabFFT {
 public:
  /// Collective: every rank constructs it with the same shape. std::runtime_error
  /// without MPI (a serial build, or no launcher).
  SlabFFT(std::size_t nx, std::size_t ny, PlanRigor rigor = PlanRigor::Measure);
  ~SlabFFT();
  SlabFFT(const SlabFFT&) = delete;
  SlabFFT& operator=(const SlabFFT&) = delete;

  /// The rows of an nx × ny grid that FFTW-MPI gives this rank (what rows() and
  /// first_row() of a SlabFFT of that shape are), without making one.
  static RowRange layout(std::size_t nx, std::size_t ny);

  std::size_t nx() const { return nx_; }
  std::size_t ny() const { return ny_; }
  /// The rows of the grid (and of the spectrum) this rank holds.
  std::size_t rows() const { return rows_; }
  std::size_t first_row() const { return first_row_; }
  std::size_t spectral_ny() const { return ny_ / 2 + 1; }
  /// Doubles per row of real(): 2 (ny/2 + 1) (FFTW-MPI pads the real rows, also out of place).
  std::size_t padded_ny() const { return 2 * spectral_ny(); }

  /// The slab's real values, rows() × padded_ny().
  double* real() { return real_; }
  const double* real() const { return real_; }
  /// The slab's modes, rows() × spectral_ny(), row-major.
  std::complex<double>* spectrum() { return spectrum_; }
  const std::complex<double>* spectrum() const { return spectrum_; }

  /// spectrum() = DFT(real()), unnormalised (collective).
  void forward();
  /// real() = IDFT without 1/N of spectrum(); spectrum() is overwritten (collective).
  void backward();
  /// Copies a slab of rows() × ny() values into real().
  void load(const double* slab);
  /// Copies real() × scale into a slab of rows() × ny() values.
  void store(double* slab, double scale = 1.0) const;

 private:
  std::size_t nx_, ny_, rows_ = 0, first_row_ = 0;
  double* real_ = nullptr;
  std::complex<double>* spectrum_ = nullptr;
  void* r2c_ = nullptr;  // fftw_plan
  void* c2r_ = nullptr;
};

}  // namespace wearscale
