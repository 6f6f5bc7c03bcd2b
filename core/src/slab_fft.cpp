#include "wearscale/core/slab_fft.hpp"

#include <omp.h>

#include <cstring>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/core/mpi.hpp"

#ifdef WEARSCALE_MPI
#include <fftw3-mpi.h>
#include <mpi.h>
#endif

namespace wearscale {

#ifdef WEARSCALE_MPI

namespace {
fftw_complex* as_fftw(std::complex<double>* p) { return reinterpret_cast<fftw_complex*>(p); }

// fftw_mpi_init once per process, after MPI_Init and fftw_init_threads (FFTPlanCache's).
void init_fftw_mpi() {
  static std::once_flag once;
  std::call_once(once, [] {
    (void)FFTPlanCache::global();
    std::lock_guard lock(detail::fftw_planner_mutex());
    fftw_mpi_init();
  });
}
}  // namespace

SlabFFT::SlabFFT(std::size_t nx, std::size_t ny, PlanRigor rigor) : nx_(nx), ny_(ny) {
  if (!mpi::active())
    throw std::runtime_error("SlabFFT: MPI is not running (start the program with mpirun or srun)");
  if (nx < 2 || ny < 2) throw std::invalid_argument("SlabFFT: the grid needs at least 2 × 2 points");
  init_fftw_mpi();
  const auto n0 = static_cast<ptrdiff_t>(nx), n1 = static_cast<ptrdiff_t>(ny);
  ptrdiff_t local_n0 = 0, local_0_start = 0;
  std::lock_guard lock(detail::fftw_planner_mutex());
  const ptrdiff_t alloc = fftw_mpi_local_size_2d(n0, n1 / 2 + 1, MPI_COMM_WORLD, &local_n0, &local_0_start);
  rows_ = static_cast<std::size_t>(local_n0);
  first_row_ = static_cast<std::size_t>(local_0_start);
  const auto cells = static_cast<std::size_t>(alloc > 0 ? alloc : 1);
  real_ = fftw_alloc_real(2 * cells);
  spectrum_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(cells));
  if (real_ == nullptr || spectrum_ == nullptr) {
    fftw_free(real_);
    fftw_free(spectrum_);
    throw std::bad_alloc();
  }
  fftw_plan_with_nthreads(omp_get_max_threads());
  const unsigned flags = detail::fftw_flags(rigor);
  r2c_ = fftw_mpi_plan_dft_r2c_2d(n0, n1, real_, as_fftw(spectrum_), MPI_COMM_WORLD, flags);
  c2r_ = fftw_mpi_plan_dft_c2r_2d(n0, n1, as_fftw(spectrum_), real_, MPI_COMM_WORLD, flags);
  if (r2c_ == nullptr || c2r_ == nullptr) {
    if (r2c_) fftw_destroy_plan(static_cast<fftw_plan>(r2c_));
    if (c2r_) fftw_destroy_plan(static_cast<fftw_plan>(c2r_));
    fftw_free(real_);
    fftw_free(spectrum_);
    throw std::runtime_error(fmt::format("FFTW-MPI could not plan a {}×{} transform", nx, ny));
  }
  // MEASURE plans overwrite the buffers: start from zeros.
  std::memset(real_, 0, 2 * cells * sizeof(double));
  std::memset(static_cast<void*>(spectrum_), 0, cells * sizeof(fftw_complex));
}

RowRange SlabFFT::layout(std::size_t nx, std::size_t ny) {
  if (!mpi::active())
    throw std::runtime_error("SlabFFT: MPI is not running (start the program with mpirun or srun)");
  init_fftw_mpi();
  ptrdiff_t local_n0 = 0, local_0_start = 0;
  std::lock_guard lock(detail::fftw_planner_mutex());
  (void)fftw_mpi_local_size_2d(static_cast<ptrdiff_t>(nx), static_cast<ptrdiff_t>(ny / 2 + 1), MPI_COMM_WORLD,
                               &local_n0, &local_0_start);
  return {static_cast<std::size_t>(local_0_start), static_cast<std::size_t>(local_n0)};
}

SlabFFT::~SlabFFT() {
  std::lock_guard lock(detail::fftw_planner_mutex());
  if (r2c_) fftw_destroy_plan(static_cast<fftw_plan>(r2c_));
  if (c2r_) fftw_destroy_plan(static_cast<fftw_plan>(c2r_));
  fftw_free(real_);
  fftw_free(spectrum_);
}

void SlabFFT::forward() { fftw_execute(static_cast<fftw_plan>(r2c_)); }
void SlabFFT::backward() { fftw_execute(static_cast<fftw_plan>(c2r_)); }

#else

SlabFFT::SlabFFT(std::size_t nx, std::size_t ny, PlanRigor) : nx_(nx), ny_(ny) {
  throw std::runtime_error("SlabFFT: this build has no MPI (configure with -DWEARSCALE_MPI=ON)");
}
RowRange SlabFFT::layout(std::size_t, std::size_t) {
  throw std::runtime_error("SlabFFT: this build has no MPI (configure with -DWEARSCALE_MPI=ON)");
}
SlabFFT::~SlabFFT() = default;
void SlabFFT::forward() {}
void SlabFFT::backward() {}

#endif

void SlabFFT::load(const double* slab) {
  const std::size_t rows = rows_, ny = ny_, pad = padded_ny();
  double* r = real_;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < rows; ++i) std::memcpy(r + i * pad, slab + i * ny, ny * sizeof(double));
}

void SlabFFT::store(double* slab, double scale) const {
  const std::size_t rows = rows_, ny = ny_, pad = padded_ny();
  const double* r = real_;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < rows; ++i)
#pragma omp simd
    for (std::size_t j = 0; j < ny; ++j) slab[i * ny + j] = scale * r[i * pad + j];
}

}  // namespace wearscale
