// Tests of the declarations a migration gives the metrics an older database recorded without one
// (store/legacy_metrics.hpp): what each name implies, as the reports of that time read it.
#include "store/legacy_metrics.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void expect_range(const std::string& metric, double min, double max) {
  const ValueRange range = inferred_declaration(metric).range;
  EXPECT_EQ(range.min, min) << metric;
  EXPECT_EQ(range.max, max) << metric;
}

TEST(LegacyMetrics, RatesLieInZeroToOneErrorsTimesAndCountsAreNonNegative) {
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

TEST(LegacyMetrics, ErrorsGetTheirUnitHeadingAndStatisticFromTheirNames) {
  const MetricDeclaration mean = inferred_declaration("post_mp_error_mean_mm");
  EXPECT_EQ(mean.unit, "mm");
  EXPECT_EQ(mean.better, Better::lower);
  EXPECT_EQ(mean.heading, "post-MP error mean / max (mm)");
  EXPECT_EQ(mean.statistic, "mean");
  EXPECT_EQ(inferred_declaration("post_mp_error_max_mm").statistic, "max");
  const MetricDeclaration held_out = inferred_declaration("full_error_max");
  EXPECT_EQ(held_out.unit, "");
  EXPECT_EQ(held_out.heading, "full error mean / max (held-out)");
  EXPECT_EQ(held_out.statistic, "max");
  EXPECT_EQ(inferred_declaration("context_error_median_mm").unit, "mm");
  EXPECT_EQ(inferred_declaration("context_error_median_mm").heading, "");
  EXPECT_EQ(inferred_declaration("task_success_rate_pull").better, Better::higher);
  EXPECT_EQ(inferred_declaration("knot_rate").better, Better::neither);
  EXPECT_EQ(inferred_declaration("failures_touched_the_corridor").better, Better::lower);
  EXPECT_EQ(inferred_declaration("cor_parameters").better, Better::neither);
}

}  // namespace
}  // namespace corrmp
