#pragma once
// Real and complex 2D fields on a Grid2D, stored in SIMD-aligned memory
// (FFTW's allocator) so FFT plans can run on any field of their shape.
#include <complex>
#include <cstddef>
#include <new>
#include <span>
#include <vector>

#include "wearscale/core/grid.hpp"

namespace wearscale {

namespace detail {
void* aligned_alloc_fftw(std::size_t bytes);
void aligned_free_fftw(void* p) noexcept;
}  // namespace detail

/// std::allocator replacement backed by fftw_malloc (SIMD alignment).
template <class T>
struct FftwAllocator {
  using value_type = T;
  FftwAllocator() = default;
  template <class U>
  FftwAllocator(const FftwAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    void* p = detail::aligned_alloc_fftw(n * sizeof(T));
    if (p == nullptr && n != 0) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) noexcept { detail::aligned_free_fftw(p); }
  template <class U>
  bool operator==(const FftwAllocator<U>&) const noexcept { return true; }
};

template <class T>
using aligned_vector = std::vector<T, FftwAllocator<T>>;

enum class Layout { Physical, Spectral };

/// Values on the points of a grid (Physical: nx × ny) or on its r2c modes
/// (Spectral: nx × (ny/2+1)).
template <class T>
class Field2D {
 public:
  Field2D() = default;
  explicit Field2D(const Grid2D& grid, Layout layout = Layout::Physical, T value = T{})
      : grid_(grid), layout_(layout),
        cols_(layout == Layout::Physical ? grid.ny : grid.spectral_ny()),
        data_(grid.nx * cols_, value) {}
  /// The spectrum of a real field on `grid` (nx × (ny/2+1) modes).
  static Field2D spectrum_of(const Grid2D& grid) { return Field2D(grid, Layout::Spectral); }

  const Grid2D& grid() const { return grid_; }
  Layout layout() const { return layout_; }
  std::size_t rows() const { return grid_.nx; }
  std::size_t cols() const { return cols_; }
  std::size_t size() const { return data_.size(); }

  T& operator()(std::size_t i, std::size_t j) { return data_[i * cols_ + j]; }
  const T& operator()(std::size_t i, std::size_t j) const { return data_[i * cols_ + j]; }
  T& operator[](std::size_t k) { return data_[k]; }
  const T& operator[](std::size_t k) const { return data_[k]; }
  /// Periodic access for physical fields: indices wrap around.
  const T& periodic(long i, long j) const { return data_[grid_.periodic_index(i, j)]; }

  T* data() { return data_.data(); }
  const T* data() const { return data_.data(); }
  std::span<T> values() { return {data_.data(), data_.size()}; }
  std::span<const T> values() const { return {data_.data(), data_.size()}; }
  auto begin() { return data_.begin(); }
  auto end() { return data_.end(); }
  auto begin() const { return data_.begin(); }
  auto end() const { return data_.end(); }
  void fill(const T& v) { std::fill(data_.begin(), data_.end(), v); }

 private:
  Grid2D grid_{};
  Layout layout_ = Layout::Physical;
  std::size_t cols_ = 0;
  aligned_vector<T> data_;
};

using RealField = Field2D<double>;
using ComplexField = Field2D<std::complex<double>>;

}  // namespace wearscale
