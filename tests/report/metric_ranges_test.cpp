// Tests of intervals clipped to a metric's declared range.
#include "report/metric_ranges.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corrmp {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

TEST(MetricRanges, ClipsOnlyTheBoundsOutsideTheRangeAndKeepsNaN) {
  const ValueRange rate = rate_metric(Better::higher).range;
  const IntervalBounds wide = clip_interval(-0.97, 1.57, rate);
  EXPECT_EQ(wide.low, 0.0);
  EXPECT_EQ(wide.high, 1.0);
  const IntervalBounds inside = clip_interval(0.25, 0.75, rate);
  EXPECT_EQ(inside.low, 0.25);
  EXPECT_EQ(inside.high, 0.75);
  const IntervalBounds error = clip_interval(-0.3, 2.5, error_metric("cm").range);
  EXPECT_EQ(error.low, 0.0);
  EXPECT_EQ(error.high, 2.5);
  const IntervalBounds free = clip_interval(-5.0, 5.0, MetricDeclaration{}.range);
  EXPECT_EQ(free.low, -5.0);
  EXPECT_EQ(free.high, 5.0);
  const IntervalBounds none = clip_interval(NAN, NAN, rate);  // one run: no interval
  EXPECT_TRUE(std::isnan(none.low));
  EXPECT_TRUE(std::isnan(none.high));

  const ValueRange difference = difference_range(rate);
  EXPECT_EQ(difference.min, -1.0);
  EXPECT_EQ(difference.max, 1.0);
  const IntervalBounds clipped = clip_interval(-2.03, 2.53, difference);
  EXPECT_EQ(clipped.low, -1.0);
  EXPECT_EQ(clipped.high, 1.0);
  EXPECT_EQ(difference_range(error_metric("cm").range).min, -kInfinity);
}

// The interval of a mean is clipped to the range its metric declares, whatever its name says.
TEST(MetricRanges, AMetricIntervalIsClippedToTheDeclaredRangeNotByTheName) {
  const MeanInterval m = mean_interval({0.9, 1.0, 0.6});
  const MetricDeclaration rate = rate_metric(Better::higher);
  EXPECT_EQ(metric_interval(rate, m).high, 1.0);
  EXPECT_EQ(metric_interval(MetricDeclaration{}, m).high, m.high);
  EXPECT_GT(m.high, 1.0);
}

}  // namespace
}  // namespace corrmp
