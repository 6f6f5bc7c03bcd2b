#pragma once
// A seeded stream of random numbers (GSL's Mersenne twister MT19937) for the
// builders: the same seed gives the same sample.
#include <gsl/gsl_rng.h>

#include <cstdint>
#include <memory>

namespace wearscale::dem {

class Random {
 public:
  explicit Random(std::uint64_t seed);
  ~Random();
  Random(Random&&) noexcept;
  Random& operator=(Random&&) noexcept;

  /// Uniform on the open interval (0, 1).
  double uniform();
  /// Uniform on [lo, hi).
  double uniform(double lo, double hi);
  /// The GSL generator, for GSL's distributions.
  gsl_rng* gsl() { return rng_.get(); }

 private:
  struct Free {
    void operator()(gsl_rng* r) const;
  };
  std::unique_ptr<gsl_rng, Free> rng_;
};

}  // namespace wearscale::dem
