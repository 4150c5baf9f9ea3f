// Tests of the Wilson score interval of a pooled proportion.
#include "stats/wilson_interval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

TEST(WilsonInterval, MatchesReferenceValues) {
  // 8 of 10 (as R's prop.test(8, 10, correct = FALSE)$conf.int).
  const ProportionInterval p = wilson_interval(8, 10);
  EXPECT_DOUBLE_EQ(p.rate, 0.8);
  EXPECT_NEAR(p.low, 0.49016247153664183, 1e-12);
  EXPECT_NEAR(p.high, 0.9433178485456247, 1e-12);
}

TEST(WilsonInterval, StaysInsideZeroToOneAtTheExtremes) {
  const ProportionInterval all = wilson_interval(25, 25);
  EXPECT_DOUBLE_EQ(all.high, 1.0);
  EXPECT_GT(all.low, 0.8);
  EXPECT_LT(all.low, 1.0);
  const ProportionInterval none = wilson_interval(0, 25);
  EXPECT_DOUBLE_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 1.0 - all.low, 1e-12);
}

TEST(WilsonInterval, HasNoRateWithoutTrialsAndRefusesImpossibleCounts) {
  EXPECT_TRUE(std::isnan(wilson_interval(0, 0).rate));
  EXPECT_THROW(wilson_interval(3, 2), std::invalid_argument);
  EXPECT_THROW(wilson_interval(-1, 2), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
