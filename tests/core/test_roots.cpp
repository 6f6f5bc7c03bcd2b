// Bracketed root finding (GSL Brent).
#include <gtest/gtest.h>

#include <cmath>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/roots.hpp"

using namespace wearscale;

TEST(Roots, FindsTheSquareRootOfTwo) {
  EXPECT_NEAR(find_root([](double x) { return x * x - 2.0; }, 0.0, 2.0, 0.0, "test"), std::sqrt(2.0), 1e-12);
}

TEST(Roots, AcceptsARootOnTheBracketEnd) {
  EXPECT_DOUBLE_EQ(find_root([](double x) { return x - 1.0; }, 0.0, 1.0, 0.0, "test"), 1.0);
}

TEST(Roots, AnInvalidBracketIsANumericalErrorNamingTheSolver) {
  try {
    find_root([](double x) { return x * x + 1.0; }, -1.0, 1.0, 0.0, "my-solver");
    FAIL();
  } catch (const NumericalError& e) {
    EXPECT_EQ(e.solver(), "my-solver");
  }
}
