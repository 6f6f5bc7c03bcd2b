#pragma once
// Real-to-complex FFTs of 2D fields through FFTW, with plans made once per
// grid shape and shared by every solver that uses that shape.
#include <complex>
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <utility>

#include "wearscale/core/field.hpp"

namespace wearscale {

/// How hard FFTW searches for a fast plan (FFTW_ESTIMATE / FFTW_MEASURE / FFTW_PATIENT).
enum class PlanRigor { Estimate, Measure, Patient };

namespace detail {
/// The lock every FFTW planner call takes (serial and MPI plans alike).
std::mutex& fftw_planner_mutex();
/// FFTW's planner flags for a rigor.
unsigned fftw_flags(PlanRigor r);
}  // namespace detail

/// modes[m] *= scale · symbol[m]: a convolution by a real, even kernel applied
/// to the modes of a half spectrum (whole or a slab's rows). The two spans must
/// have the same length (std::invalid_argument otherwise).
void multiply_modes(std::span<std::complex<double>> modes, std::span<const double> symbol, double scale = 1.0);

/// A forward (r2c) and backward (c2r) transform pair for one nx × ny shape.
/// Thread-safe to execute concurrently on different fields.
class FFTPlan {
 public:
  FFTPlan(std::size_t nx, std::size_t ny, PlanRigor rigor, int threads);
  ~FFTPlan();
  FFTPlan(const FFTPlan&) = delete;
  FFTPlan& operator=(const FFTPlan&) = delete;

  /// ĥ(k) = Σ_x h(x) e^{-i k·x}: unnormalised forward transform. `in` is preserved.
  void forward(const RealField& in, ComplexField& out) const;
  /// h(x) = (1/N) Σ_k ĥ(k) e^{i k·x}: normalised inverse. `in` is overwritten (FFTW c2r).
  void backward(ComplexField& in, RealField& out) const;
  /// Inverse without the 1/N factor, for callers that fold it into an operator.
  void backward_unnormalized(ComplexField& in, RealField& out) const;

  std::size_t nx() const { return nx_; }
  std::size_t ny() const { return ny_; }
  int threads() const { return threads_; }

 private:
  void check(const Grid2D& g, const char* what) const;
  std::size_t nx_, ny_;
  int threads_;
  void* r2c_ = nullptr;  // fftw_plan (opaque here to keep fftw3.h out of headers)
  void* c2r_ = nullptr;
};

/// Process-wide cache: the same shape always returns the same plan object.
class FFTPlanCache {
 public:
  static FFTPlanCache& global();

  std::shared_ptr<const FFTPlan> plan(std::size_t nx, std::size_t ny);
  std::shared_ptr<const FFTPlan> plan(const Grid2D& g) { return plan(g.nx, g.ny); }

  void set_rigor(PlanRigor r);
  /// Threads for plans made from now on; 0 = OpenMP's maximum. Grids smaller
  /// than `threaded_min_size` points always use one thread (threads cost more
  /// than they save there).
  void set_threads(int threads, std::size_t threaded_min_size = 128 * 128);
  /// FFTW wisdom makes MEASURE/PATIENT planning instantaneous on later runs.
  bool import_wisdom(const std::filesystem::path& file);
  void export_wisdom(const std::filesystem::path& file) const;
  /// The same as text (stored in checkpoints so a resumed run plans alike).
  std::string export_wisdom_string() const;
  bool import_wisdom_string(const std::string& wisdom);
  std::size_t size() const;
  void clear();

 private:
  FFTPlanCache();
  mutable std::mutex mutex_;
  std::map<std::pair<std::size_t, std::size_t>, std::shared_ptr<const FFTPlan>> plans_;
  PlanRigor rigor_ = PlanRigor::Measure;
  int threads_ = 0;
  std::size_t threaded_min_size_ = 128 * 128;
};

}  // namespace wearscale
