#include "wearscale/core/fft.hpp"

#include <fftw3.h>
#include <omp.h>

#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"

namespace wearscale {

namespace detail {
void* aligned_alloc_fftw(std::size_t bytes) { return fftw_malloc(bytes); }
void aligned_free_fftw(void* p) noexcept { fftw_free(p); }
// FFTW's planner is not thread-safe; every plan creation/destruction and
// wisdom access (serial or MPI plans) goes through this lock. Execution needs no lock.
std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}
unsigned fftw_flags(PlanRigor r) {
  switch (r) {
    case PlanRigor::Estimate: return FFTW_ESTIMATE;
    case PlanRigor::Measure: return FFTW_MEASURE;
    case PlanRigor::Patient: return FFTW_PATIENT;
  }
  return FFTW_ESTIMATE;
}
}  // namespace detail

namespace {
std::mutex& planner_mutex() { return detail::fftw_planner_mutex(); }
unsigned flags_of(PlanRigor r) { return detail::fftw_flags(r); }

fftw_complex* as_fftw(std::complex<double>* p) { return reinterpret_cast<fftw_complex*>(p); }
}  // namespace

void multiply_modes(std::span<std::complex<double>> modes, std::span<const double> symbol, double scale) {
  if (modes.size() != symbol.size())
    throw std::invalid_argument(fmt::format("multiply_modes: {} modes, {} values of the symbol", modes.size(),
                                            symbol.size()));
  std::complex<double>* s = modes.data();
  const double* k = symbol.data();
  const std::size_t n = modes.size();
#pragma omp parallel for simd schedule(static)
  for (std::size_t m = 0; m < n; ++m) s[m] *= scale * k[m];
}

FFTPlan::FFTPlan(std::size_t nx, std::size_t ny, PlanRigor rigor, int threads)
    : nx_(nx), ny_(ny), threads_(threads) {
  if (nx == 0 || ny == 0) throw std::invalid_argument("FFTPlan: empty grid");
  // Plan on scratch arrays (MEASURE overwrites them) and later execute on the
  // caller's fields with the new-array interface; all fields are
  // fftw_malloc'ed, so their alignment matches the scratch arrays'.
  const Grid2D g(nx, ny, 1.0, 1.0);
  RealField real(g);
  ComplexField spec = ComplexField::spectrum_of(g);
  std::lock_guard lock(planner_mutex());
  fftw_plan_with_nthreads(threads);
  const int n0 = static_cast<int>(nx), n1 = static_cast<int>(ny);
  r2c_ = fftw_plan_dft_r2c_2d(n0, n1, real.data(), as_fftw(spec.data()), flags_of(rigor));
  c2r_ = fftw_plan_dft_c2r_2d(n0, n1, as_fftw(spec.data()), real.data(), flags_of(rigor));
  if (r2c_ == nullptr || c2r_ == nullptr)
    throw std::runtime_error(fmt::format("FFTW could not plan a {}×{} transform", nx, ny));
}

FFTPlan::~FFTPlan() {
  std::lock_guard lock(planner_mutex());
  if (r2c_) fftw_destroy_plan(static_cast<fftw_plan>(r2c_));
  if (c2r_) fftw_destroy_plan(static_cast<fftw_plan>(c2r_));
}

void FFTPlan::check(const Grid2D& g, const char* what) const {
  if (g.nx != nx_ || g.ny != ny_)
    throw std::invalid_argument(fmt::format("FFTPlan {}×{}: {} field is {}×{}", nx_, ny_, what, g.nx, g.ny));
}

void FFTPlan::forward(const RealField& in, ComplexField& out) const {
  check(in.grid(), "input");
  check(out.grid(), "output");
  if (in.layout() != Layout::Physical || out.layout() != Layout::Spectral)
    throw std::invalid_argument("FFTPlan::forward: expects a physical input and a spectral output");
  // Out-of-place r2c never touches its input (FFTW manual §4.3.2).
  fftw_execute_dft_r2c(static_cast<fftw_plan>(r2c_), const_cast<double*>(in.data()), as_fftw(out.data()));
}

void FFTPlan::backward_unnormalized(ComplexField& in, RealField& out) const {
  check(in.grid(), "input");
  check(out.grid(), "output");
  if (in.layout() != Layout::Spectral || out.layout() != Layout::Physical)
    throw std::invalid_argument("FFTPlan::backward: expects a spectral input and a physical output");
  fftw_execute_dft_c2r(static_cast<fftw_plan>(c2r_), as_fftw(in.data()), out.data());
}

void FFTPlan::backward(ComplexField& in, RealField& out) const {
  backward_unnormalized(in, out);
  const double scale = 1.0 / static_cast<double>(nx_ * ny_);
  double* o = out.data();
  const std::size_t n = out.size();
#pragma omp simd
  for (std::size_t k = 0; k < n; ++k) o[k] *= scale;
}

FFTPlanCache::FFTPlanCache() {
  std::lock_guard lock(planner_mutex());
  fftw_init_threads();
}

FFTPlanCache& FFTPlanCache::global() {
  static FFTPlanCache cache;
  return cache;
}

std::shared_ptr<const FFTPlan> FFTPlanCache::plan(std::size_t nx, std::size_t ny) {
  std::lock_guard lock(mutex_);
  auto key = std::make_pair(nx, ny);
  if (auto it = plans_.find(key); it != plans_.end()) return it->second;
  const int threads = nx * ny < threaded_min_size_ ? 1 : (threads_ > 0 ? threads_ : omp_get_max_threads());
  auto p = std::make_shared<const FFTPlan>(nx, ny, rigor_, threads);
  plans_.emplace(key, p);
  return p;
}

void FFTPlanCache::set_rigor(PlanRigor r) {
  std::lock_guard lock(mutex_);
  // A plan of the other rigor is not reused: a measured plan picks its
  // algorithm by timing, so it may round otherwise than an estimated one.
  if (r != rigor_) plans_.clear();
  rigor_ = r;
}

void FFTPlanCache::set_threads(int threads, std::size_t threaded_min_size) {
  std::lock_guard lock(mutex_);
  threads_ = threads;
  threaded_min_size_ = threaded_min_size;
}

bool FFTPlanCache::import_wisdom(const std::filesystem::path& file) {
  std::lock_guard lock(planner_mutex());
  return fftw_import_wisdom_from_filename(file.c_str()) != 0;
}

void FFTPlanCache::export_wisdom(const std::filesystem::path& file) const {
  std::lock_guard lock(planner_mutex());
  // Wisdom is a cache: write it beside and rename, never leave half a file.
  const auto tmp = partial_path(file);
  if (fftw_export_wisdom_to_filename(tmp.c_str()) == 0)
    throw std::runtime_error("cannot write FFTW wisdom to " + file.string());
  commit_file(tmp, file);
}

std::string FFTPlanCache::export_wisdom_string() const {
  std::lock_guard lock(planner_mutex());
  char* text = fftw_export_wisdom_to_string();
  if (text == nullptr) return {};
  std::string out(text);
  fftw_free(text);
  return out;
}

bool FFTPlanCache::import_wisdom_string(const std::string& wisdom) {
  std::lock_guard lock(planner_mutex());
  return fftw_import_wisdom_from_string(wisdom.c_str()) != 0;
}

std::size_t FFTPlanCache::size() const {
  std::lock_guard lock(mutex_);
  return plans_.size();
}

void FFTPlanCache::clear() {
  std::lock_guard lock(mutex_);
  plans_.clear();
}

}  // namespace wearscale
