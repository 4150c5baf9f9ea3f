// Tests of metric value ranges by name and intervals clipped to them.
#include "report/metric_ranges.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corrmp {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void expect_range(const std::string& metric, double min, double max) {
  const ValueRange range = metric_range(metric);
  EXPECT_EQ(range.min, min) << metric;
  EXPECT_EQ(range.max, max) << metric;
}

TEST(MetricRanges, RatesLieInZeroToOneErrorsTimesAndCountsAreNonNegative) {
  for (const char* rate : {"task_success_rate", "decision_match_rate", "task_success_rate_push",
                           "decision_match_rate_none", "context_found_rate", "knot_rate",
                           "demonstrations_context_found_rate"}) {
    expect_range(rate, 0.0, 1.0);
  }
  for (const char* non_negative :
       {"cor_mp_error_mean_cm", "post_mp_error_max_cm", "pre_mp_error_mean_mm",
        "context_error_median_mm", "cor_error_mean", "rope_end_distance_m", "training_time",
        "collection_seconds", "expected_push", "failures_missed", "demonstrations_train",
        "cor_parameters", "autoencoder_train_mse", "autoencoder_test_mse"}) {
    expect_range(non_negative, 0.0, kInfinity);
  }
  for (const char* unbounded : {"offset_x", "rates", "terror", "msec"}) {
    expect_range(unbounded, -kInfinity, kInfinity);
  }
}

TEST(MetricRanges, ClipsOnlyTheBoundsOutsideTheRangeAndKeepsNaN) {
  const ValueRange rate = metric_range("task_success_rate");
  const IntervalBounds wide = clip_interval(-0.97, 1.57, rate);
  EXPECT_EQ(wide.low, 0.0);
  EXPECT_EQ(wide.high, 1.0);
  const IntervalBounds inside = clip_interval(0.25, 0.75, rate);
  EXPECT_EQ(inside.low, 0.25);
  EXPECT_EQ(inside.high, 0.75);
  const IntervalBounds error = clip_interval(-0.3, 2.5, metric_range("cor_mp_error_mean_cm"));
  EXPECT_EQ(error.low, 0.0);
  EXPECT_EQ(error.high, 2.5);
  const IntervalBounds free = clip_interval(-5.0, 5.0, metric_range("offset_x"));
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
  EXPECT_EQ(difference_range(metric_range("cor_mp_error_mean_cm")).min, -kInfinity);
}

}  // namespace
}  // namespace corrmp
