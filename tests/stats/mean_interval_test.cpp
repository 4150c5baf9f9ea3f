// Tests of means across seeds with Student t intervals and of Welch's interval
// for a difference of means (reference values from mpmath, 30 digits).
#include "stats/mean_interval.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

TEST(MeanInterval, UsesStudentTWithNMinusOneDegreesOfFreedom) {
  const MeanInterval m = mean_interval({1, 2, 3, 4, 5});
  EXPECT_EQ(m.count, 5);
  EXPECT_DOUBLE_EQ(m.mean, 3.0);
  EXPECT_NEAR(m.stddev, std::sqrt(2.5), 1e-14);
  // t(0.975, 4) * sqrt(2.5) / sqrt(5)
  EXPECT_NEAR(m.half_width, 1.96324316148, 1e-10);
  EXPECT_NEAR(m.low, 3.0 - 1.96324316148, 1e-10);
  EXPECT_NEAR(m.high, 3.0 + 1.96324316148, 1e-10);
  EXPECT_TRUE(m.defined());
}

TEST(MeanInterval, NarrowsWithLowerConfidence) {
  const MeanInterval wide = mean_interval({0.96, 0.92, 1.0});
  EXPECT_NEAR(wide.half_width, 0.09936550847, 1e-10);
  EXPECT_LT(mean_interval({0.96, 0.92, 1.0}, 0.8).half_width, wide.half_width);
}

TEST(MeanInterval, IsUndefinedForOneSampleAndHasNoMeanForNone) {
  const MeanInterval one = mean_interval({0.7});
  EXPECT_EQ(one.count, 1);
  EXPECT_DOUBLE_EQ(one.mean, 0.7);
  EXPECT_FALSE(one.defined());
  EXPECT_TRUE(std::isnan(one.half_width));
  EXPECT_TRUE(std::isnan(one.low));
  EXPECT_TRUE(std::isnan(one.high));
  const MeanInterval none = mean_interval({});
  EXPECT_EQ(none.count, 0);
  EXPECT_TRUE(std::isnan(none.mean));
  EXPECT_FALSE(none.defined());
}

TEST(MeanInterval, IsThePointWhenAllSeedsAgree) {
  const MeanInterval m = mean_interval({1.0, 1.0, 1.0});
  EXPECT_TRUE(m.defined());
  EXPECT_EQ(m.half_width, 0.0);
  EXPECT_EQ(m.low, 1.0);
  EXPECT_EQ(m.high, 1.0);
}

TEST(MeanInterval, RefusesAConfidenceOutsideZeroToOne) {
  EXPECT_THROW(mean_interval({1, 2}, 1.0), std::invalid_argument);
  EXPECT_THROW(difference_interval({1, 2}, {1, 2}, 0.0), std::invalid_argument);
}

TEST(DifferenceInterval, UsesWelchDegreesOfFreedom) {
  const DifferenceInterval d = difference_interval({1, 2, 3}, {2, 4, 6, 8});
  EXPECT_DOUBLE_EQ(d.difference, 3.0);  // mean(b) - mean(a)
  EXPECT_NEAR(d.dof, 4.075471698113207, 1e-12);
  EXPECT_NEAR(d.half_width, 3.89797545108, 1e-9);
  EXPECT_NEAR(d.low, 3.0 - 3.89797545108, 1e-9);
  EXPECT_TRUE(d.defined());
}

TEST(DifferenceInterval, IsUndefinedWhenAGroupHasOneRun) {
  const DifferenceInterval d = difference_interval({0.5}, {0.9, 1.0});
  EXPECT_DOUBLE_EQ(d.difference, 0.45);
  EXPECT_FALSE(d.defined());
  EXPECT_TRUE(std::isnan(d.low));
  const DifferenceInterval flat = difference_interval({1.0, 1.0}, {0.5, 0.5});
  EXPECT_TRUE(flat.defined());
  EXPECT_EQ(flat.low, -0.5);
  EXPECT_EQ(flat.high, -0.5);
}

}  // namespace
}  // namespace corrmp
