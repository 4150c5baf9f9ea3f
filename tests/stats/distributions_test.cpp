// Tests of the Student t and normal distributions: quantiles against printed
// tables (t(0.975, 4) = 2.776), closed forms for 1 and 2 degrees of freedom,
// and non-integer degrees of freedom against mpmath (30 digits).
#include "stats/distributions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

TEST(StudentT, QuantilesMatchTables) {
  EXPECT_NEAR(student_t_quantile(0.975, 1), 12.70620474, 1e-7);
  EXPECT_NEAR(student_t_quantile(0.975, 2), 4.30265273, 1e-7);
  EXPECT_NEAR(student_t_quantile(0.975, 4), 2.776445105, 1e-8);
  EXPECT_NEAR(student_t_quantile(0.975, 9), 2.262157163, 1e-8);
  EXPECT_NEAR(student_t_quantile(0.975, 29), 2.045229642, 1e-8);
  EXPECT_NEAR(student_t_quantile(0.975, 1000), 1.962339081, 1e-8);
  EXPECT_NEAR(student_t_quantile(0.995, 10), 3.169272673, 1e-8);
  EXPECT_NEAR(student_t_quantile(0.95, 20), 1.724718243, 1e-8);
}

TEST(StudentT, QuantilesForNonIntegerDegreesOfFreedom) {  // Welch's intervals need them
  EXPECT_NEAR(student_t_quantile(0.975, 2.5), 3.574654842, 1e-8);
  EXPECT_NEAR(student_t_quantile(0.975, 7.3), 2.345066737, 1e-8);
  EXPECT_NEAR(student_t_cdf(1.5, 3.7), 0.893200915399, 1e-11);
}

TEST(StudentT, MatchesClosedFormsForOneAndTwoDegreesOfFreedom) {
  const double pi = std::acos(-1.0);
  for (double p : {0.001, 0.1, 0.4, 0.6, 0.9, 0.975, 0.9995}) {
    // Cauchy: tan(pi (p - 1/2)); two degrees of freedom: (2p - 1) / sqrt(2 p (1 - p)).
    const double cauchy = std::tan(pi * (p - 0.5));
    const double two = (2 * p - 1) / std::sqrt(2 * p * (1 - p));
    EXPECT_NEAR(student_t_quantile(p, 1), cauchy, 1e-9 * std::max(1.0, std::fabs(cauchy))) << p;
    EXPECT_NEAR(student_t_quantile(p, 2), two, 1e-10 * std::max(1.0, std::fabs(two))) << p;
  }
}

TEST(StudentT, IsSymmetricAndInvertsItsCdf) {
  EXPECT_EQ(student_t_quantile(0.5, 3), 0.0);
  EXPECT_DOUBLE_EQ(student_t_quantile(0.025, 4), -student_t_quantile(0.975, 4));
  EXPECT_DOUBLE_EQ(student_t_cdf(0.0, 6), 0.5);
  for (double p : {0.01, 0.3, 0.77, 0.999}) {
    EXPECT_NEAR(student_t_cdf(student_t_quantile(p, 5.5), 5.5), p, 1e-14) << p;
  }
}

TEST(StudentT, RefusesBadArguments) {
  EXPECT_THROW(student_t_quantile(0.0, 3), std::invalid_argument);
  EXPECT_THROW(student_t_quantile(1.0, 3), std::invalid_argument);
  EXPECT_THROW(student_t_quantile(0.9, 0), std::invalid_argument);
  EXPECT_THROW(student_t_cdf(1.0, -2), std::invalid_argument);
}

TEST(Normal, QuantilesMatchTables) {
  EXPECT_NEAR(normal_quantile(0.975), 1.959963984540054, 1e-12);
  EXPECT_NEAR(normal_quantile(0.995), 2.575829303548901, 1e-12);
  EXPECT_NEAR(normal_quantile(0.1), -1.281551565544601, 1e-12);
  EXPECT_NEAR(normal_cdf(1.0), 0.841344746068543, 1e-14);
}

}  // namespace
}  // namespace corrmp
