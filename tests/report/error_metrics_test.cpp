// Tests of report/error_metrics.hpp: which metric names are trajectory errors, and the
// columns the run table and the comparison give them.
#include "report/error_metrics.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

TEST(ErrorMetrics, ClosedLoopAndHeldOutErrorsAreRecognisedOthersAreNot) {
  const auto closed_loop = error_metric("cor_mp_error_mean_cm");
  ASSERT_TRUE(closed_loop);
  EXPECT_EQ(closed_loop->max, "cor_mp_error_max_cm");
  EXPECT_EQ(closed_loop->heading, "cor-MP error mean / max (cm)");

  const auto held_out = error_metric("full_error_mean");  // a run with no environment
  ASSERT_TRUE(held_out);
  EXPECT_EQ(held_out->max, "full_error_max");
  EXPECT_EQ(held_out->heading, "full error mean / max (held-out)");

  for (const char* other : {"cor_mp_error_max_cm", "full_error_max", "context_error_median_mm",
                            "context_error_max_mm", "task_success_rate", "_error_mean",
                            "_mp_error_mean_cm", "cor_mp_error_mean_", "autoencoder_test_mse"})
    EXPECT_FALSE(error_metric(other)) << other;
}

TEST(ErrorMetrics, EachErrorOnceInTheOrderTheRunsRecordedThem) {
  RunSummary corridor, curves;
  corridor.metric_order = {"task_success_rate", "cor_mp_error_mean_cm", "cor_mp_error_max_cm",
                           "post_mp_error_mean_cm", "post_mp_error_max_cm"};
  curves.metric_order = {"full_error_mean", "full_error_max", "cor_mp_error_mean_cm"};
  const auto errors = error_metrics({corridor, curves});
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].mean, "cor_mp_error_mean_cm");
  EXPECT_EQ(errors[1].mean, "post_mp_error_mean_cm");
  EXPECT_EQ(errors[2].mean, "full_error_mean");
}

}  // namespace
}  // namespace corrmp
