// Tests of the evaluation's metrics and tables: they follow what the task
// declares (decision labels or none, error segments and unit, outcome
// metrics, failure categories) and name no task.
#include "evaluation/evaluation_tables.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

EvaluatedTrial trial(bool success, const std::string& failure, const std::string& expected,
                     const std::string& chosen, double knot) {
  EvaluatedTrial t;
  t.success = success;
  t.failure = failure;
  t.expected_action = expected;
  t.chosen_action = chosen;
  t.outcome["knot"] = knot;
  return t;
}

std::map<std::string, double> as_map(const std::vector<MetricRecord>& metrics) {
  std::map<std::string, double> out;
  for (const auto& m : metrics) {
    EXPECT_EQ(out.count(m.name), 0u) << m.name;
    out[m.name] = m.value;
  }
  return out;
}

TEST(EvaluationTables, DecisionsErrorsOutcomesAndFailuresFollowTheTask) {
  TaskReport task;
  task.error_unit = "mm";
  task.error_segments = {"a", "b"};
  task.decision_labels = {"left", "right"};
  task.outcome_metrics = {"knot"};
  task.failure_categories = {"missed enclose", "near miss"};
  const std::vector<EvaluatedTrial> trials{
      trial(true, "", "left", "left", 1),
      trial(false, "missed enclose: 0 nodes", "left", "right", 0),
      trial(false, "near miss", "right", "right", 0), trial(true, "", "right", "right", 1)};
  const std::map<std::string, TrajectoryError> errors{{"a", {1.5, 3.0}}};
  const auto m = as_map(evaluation_metrics(task, true, trials, errors));
  EXPECT_DOUBLE_EQ(m.at("task_success_rate"), 0.5);
  EXPECT_DOUBLE_EQ(m.at("decision_match_rate"), 0.75);
  EXPECT_DOUBLE_EQ(m.at("a_mp_error_mean_mm"), 1.5);
  EXPECT_DOUBLE_EQ(m.at("a_mp_error_max_mm"), 3.0);
  EXPECT_EQ(m.count("b_mp_error_mean_mm"), 0u);  // no error measured for b
  EXPECT_DOUBLE_EQ(m.at("expected_left"), 2);
  EXPECT_DOUBLE_EQ(m.at("decision_match_rate_left"), 0.5);
  EXPECT_DOUBLE_EQ(m.at("task_success_rate_right"), 0.5);
  EXPECT_DOUBLE_EQ(m.at("knot_rate"), 0.5);
  EXPECT_DOUBLE_EQ(m.at("failures_missed_enclose"), 1);
  EXPECT_DOUBLE_EQ(m.at("failures_near_miss"), 1);

  const std::string tables = evaluation_tables(task, true, trials, errors, "t");
  EXPECT_NE(tables.find("Table I (t): 2 of 4 trials succeeded, decision match 75%"),
            std::string::npos)
      << tables;
  EXPECT_NE(tables.find("1 left, 1 right"), std::string::npos) << tables;
  EXPECT_NE(tables.find("Table II (t): prediction errors (mm)"), std::string::npos) << tables;
  EXPECT_NE(tables.find("a-MP"), std::string::npos) << tables;
  EXPECT_NE(tables.find("knot"), std::string::npos) << tables;
  EXPECT_NE(tables.find("missed enclose"), std::string::npos) << tables;
}

// A long action choice (the rope's many correction types) widens its column, so the
// percentages still line up under their headings.
TEST(EvaluationTables, ALongActionChoiceKeepsTheColumnsAligned) {
  TaskReport task;
  task.decision_labels = {"a", "b"};
  std::vector<EvaluatedTrial> trials{trial(true, "", "a", "a", 1)};
  for (const char* chosen :
       {"anterior-to-posterior", "posterior-to-anterior", "combined", "lateral", "vertical"})
    trials.push_back(trial(true, "", "b", chosen, 1));
  const std::string tables = evaluation_tables(task, true, trials, {}, "t");
  std::vector<std::string> lines;
  for (size_t at = 0, end; (end = tables.find('\n', at)) != std::string::npos; at = end + 1)
    lines.push_back(tables.substr(at, end - at));
  ASSERT_GE(lines.size(), 4u) << tables;
  const size_t heading_end = lines[1].size(), row_a_end = lines[2].size();
  EXPECT_EQ(row_a_end, heading_end) << tables;
  EXPECT_EQ(lines[3].size(), heading_end) << tables;
  EXPECT_NE(lines[3].find("1 anterior-to-posterior, 1 combined, 1 lateral, 1 "
                          "posterior-to-anterior, 1 vertical "),
            std::string::npos)
      << tables;
}

TEST(EvaluationTables, APolicyThatMakesNoDecisionHasNoDecisionMatch) {
  TaskReport task;
  task.decision_labels = {"left", "right"};
  const std::vector<EvaluatedTrial> trials{trial(true, "", "left", "", 1),
                                           trial(false, "x", "right", "", 0)};
  const auto m = as_map(evaluation_metrics(task, false, trials, {}));
  EXPECT_EQ(m.count("decision_match_rate"), 0u);
  EXPECT_EQ(m.count("decision_match_rate_left"), 0u);
  EXPECT_DOUBLE_EQ(m.at("expected_left"), 1);
  EXPECT_DOUBLE_EQ(m.at("task_success_rate_left"), 1);
  const std::string tables = evaluation_tables(task, false, trials, {}, "t");
  EXPECT_NE(tables.find("1 of 2 trials succeeded, decision match -"), std::string::npos) << tables;
}

TEST(EvaluationTables, ATaskWithoutDecisionsHasNoDecisionMetrics) {
  TaskReport task;
  const std::vector<EvaluatedTrial> trials{trial(true, "", "", "", 1),
                                           trial(false, "x", "", "", 0)};
  const auto m = as_map(evaluation_metrics(task, false, trials, {}));
  EXPECT_DOUBLE_EQ(m.at("task_success_rate"), 0.5);
  EXPECT_EQ(m.count("decision_match_rate"), 0u);
  const std::string tables = evaluation_tables(task, false, trials, {}, "t");
  EXPECT_NE(tables.find("Task success (t): 1 of 2 trials succeeded"), std::string::npos) << tables;
  EXPECT_EQ(tables.find("Table I"), std::string::npos) << tables;
  EXPECT_EQ(tables.find("Table II"), std::string::npos) << tables;
}

}  // namespace
}  // namespace corrmp
