// Tests of the regularized incomplete beta function against closed forms and
// values computed independently (mpmath.betainc, 30 digits).
#include "stats/incomplete_beta.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

TEST(IncompleteBeta, MatchesClosedForms) {
  for (double x : {0.01, 0.2, 0.5, 0.77, 0.99}) {
    EXPECT_NEAR(regularized_incomplete_beta(3.5, 1.0, x), std::pow(x, 3.5), 1e-14) << x;
    EXPECT_NEAR(regularized_incomplete_beta(1.0, 2.5, x), 1.0 - std::pow(1.0 - x, 2.5), 1e-14) << x;
  }
  EXPECT_NEAR(regularized_incomplete_beta(7.0, 7.0, 0.5), 0.5, 1e-14);
  EXPECT_EQ(regularized_incomplete_beta(2.0, 3.0, 0.0), 0.0);
  EXPECT_EQ(regularized_incomplete_beta(2.0, 3.0, 1.0), 1.0);
}

TEST(IncompleteBeta, MatchesReferenceValues) {
  EXPECT_NEAR(regularized_incomplete_beta(2.5, 3.5, 0.3), 0.296752989295666, 1e-13);
  EXPECT_NEAR(regularized_incomplete_beta(30.0, 40.0, 0.45), 0.644748008558568, 1e-12);
  EXPECT_NEAR(regularized_incomplete_beta(0.5, 0.5, 0.1), 0.204832764699133, 1e-13);
}

TEST(IncompleteBeta, RefusesArgumentsOutsideItsDomain) {
  EXPECT_THROW(regularized_incomplete_beta(0.0, 1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(regularized_incomplete_beta(1.0, -1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(regularized_incomplete_beta(1.0, 1.0, 1.5), std::invalid_argument);
  EXPECT_THROW(regularized_incomplete_beta(1.0, 1.0, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
