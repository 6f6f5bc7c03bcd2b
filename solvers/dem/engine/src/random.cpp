#include "wearscale/dem/random.hpp"

#include <gsl/gsl_rng.h>

#include <stdexcept>

namespace wearscale::dem {

void Random::Free::operator()(gsl_rng* r) const { gsl_rng_free(r); }

Random::Random(std::uint64_t seed) : rng_(gsl_rng_alloc(gsl_rng_mt19937)) {
  if (!rng_) throw std::bad_alloc();
  // MT19937 uses the low 32 bits of the seed (0 selects GSL's default, 4357).
  gsl_rng_set(rng_.get(), static_cast<unsigned long>(seed));
}

Random::~Random() = default;
Random::Random(Random&&) noexcept = default;
Random& Random::operator=(Random&&) noexcept = default;

double Random::uniform() { return gsl_rng_uniform_pos(rng_.get()); }

double Random::uniform(double lo, double hi) { return lo + (hi - lo) * gsl_rng_uniform(rng_.get()); }

}  // namespace wearscale::dem
