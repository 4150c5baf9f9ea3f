// Tests of report/error_metrics.hpp: which of a run's metrics are trajectory errors (what they
// were declared as), and the columns the run table and the comparison give them.
#include "report/error_metrics.hpp"

#include <gtest/gtest.h>

#include "store/legacy_metrics.hpp"

namespace corrmp {
namespace {

// A run that recorded `names`, each declared as the code recording it declares it (which a
// migration gives an older database's metrics too).
RunSummary run_recording(const std::vector<std::string>& names) {
  RunSummary run;
  for (const auto& name : names) {
    run.metric_order.push_back(name);
    run.metrics[name] = 1.0;
    run.declarations[name] = inferred_declaration(name);
  }
  return run;
}

TEST(ErrorMetrics, ClosedLoopAndHeldOutErrorsAreRecognisedOthersAreNot) {
  const auto closed_loop =
      error_metrics({run_recording({"cor_mp_error_mean_cm", "cor_mp_error_max_cm"})});
  ASSERT_EQ(closed_loop.size(), 1u);
  EXPECT_EQ(closed_loop[0].max, "cor_mp_error_max_cm");
  EXPECT_EQ(closed_loop[0].heading, "cor-MP error mean / max (cm)");

  // a run with no environment
  const auto held_out = error_metrics({run_recording({"full_error_mean", "full_error_max"})});
  ASSERT_EQ(held_out.size(), 1u);
  EXPECT_EQ(held_out[0].max, "full_error_max");
  EXPECT_EQ(held_out[0].heading, "full error mean / max (held-out)");

  for (const char* other : {"cor_mp_error_max_cm", "full_error_max", "context_error_median_mm",
                            "context_error_max_mm", "task_success_rate", "_error_mean",
                            "_mp_error_mean_cm", "cor_mp_error_mean_", "autoencoder_test_mse"})
    EXPECT_TRUE(error_metrics({run_recording({other})}).empty()) << other;
}

TEST(ErrorMetrics, EachErrorOnceInTheOrderTheRunsRecordedThem) {
  const RunSummary corridor =
      run_recording({"task_success_rate", "cor_mp_error_mean_cm", "cor_mp_error_max_cm",
                     "post_mp_error_mean_cm", "post_mp_error_max_cm"});
  const RunSummary curves =
      run_recording({"full_error_mean", "full_error_max", "cor_mp_error_mean_cm"});
  const auto errors = error_metrics({corridor, curves});
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].mean, "cor_mp_error_mean_cm");
  EXPECT_EQ(errors[1].mean, "post_mp_error_mean_cm");
  EXPECT_EQ(errors[2].mean, "full_error_mean");
}

// A column is what a run declared: a mean and a max under one heading, whatever their names; a
// name that looks like an error but was declared as nothing of the kind gets no column.
TEST(ErrorMetrics, AColumnIsWhatTheRunDeclaredWhateverTheNames) {
  RunSummary run;
  const std::string heading = "reach-MP error mean / max (mm)";
  run.metric_order = {"first", "second", "cor_mp_error_mean_cm"};
  run.declarations["first"] = error_statistic("mm", heading, "mean");
  run.declarations["second"] = error_statistic("mm", heading, "max");
  run.declarations["cor_mp_error_mean_cm"] = MetricDeclaration{};
  const auto errors = error_metrics({run});
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].mean, "first");
  EXPECT_EQ(errors[0].max, "second");
  EXPECT_EQ(errors[0].heading, heading);
}

}  // namespace
}  // namespace corrmp
