// Tests of a reference's decision and error tables beside our runs, for a
// made-up task with labels up and down: the tables follow the spec read from
// YAML, the spec's numbers must be for its labels and errors, and the same
// numbers give the run table's reference rows.
#include "report/decision_tables.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "core/config/config_loader.hpp"
#include "core/config/config_reader.hpp"

namespace corrmp {
namespace {

using testing::config_error_of;
using testing::TempDir;

const std::string kSpec = R"yaml(decision_tables:
  environment: lift
  decision_table: t1
  decision_title: "Lifts: decisions"
  error_table: t2
  error_title: "Lifts: errors (mm)"
  column_kind: Method
  verdicts_of: the lift tables
  absent_title: Lift tables
  absent_text: No lift runs.
  labels: [{name: up, printed: Up}, {name: down, printed: Down}]
  expected: {up: 3, down: 1}
  errors: [{heading: arc, mean: arc_error_mean_mm, max: arc_error_max_mm}]
  rate_rounding: 0.005
  error_rounding: 0.05
  columns:
    - experiment: lift_a
      key: a
      heading: A
      task_successes: 3
      decision_match: {up: 1.0, down: 0.0}
      task_success_rate: {up: 1.0, down: 0.0}
      action_choice: {up: 3 Up, down: 1 Up}
      errors: {arc_error_mean_mm: 1.5, arc_error_max_mm: 4.0}
)yaml";

struct Tables {
  DecisionTablesSpec decision_tables;
  template <class Fields>
  void describe(Fields& f) {
    f("decision_tables", decision_tables, "the tables");
  }
};

DecisionTablesSpec read_spec(const TempDir& dir, const std::string& text) {
  ConfigNode root = load_config(dir.write("spec.yaml", text), {});
  Tables tables;
  ConfigReader::read(root, "", tables);
  check_decision_tables(tables.decision_tables, *root.find("decision_tables"), "decision_tables");
  return tables.decision_tables;
}

TEST(DecisionTables, FollowTheSpecsLabelsColumnsAndErrors) {
  TempDir dir;
  const DecisionTablesSpec spec = read_spec(dir, kSpec);
  RunSummary run;
  run.experiment = "lift_a";
  run.by_expected["up"].chosen = {{"up", 2}, {"down", 1}};
  run.metrics = {{"decision_match_rate_up", 2.0 / 3}, {"arc_error_mean_mm", 1.2}};
  ReportCells cells;
  const std::string md = decision_tables_section(spec, {{"lift_a", {&run}}}, cells);
  EXPECT_EQ(md.rfind("## Lifts: decisions\n\n### Action choice\n\n", 0), 0u) << md;
  EXPECT_NE(md.find("| Expected correction | A | A paper |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| Up | 2 Up, 1 Down (1 run) | 3 Up |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| Down | never expected | 1 Up |\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| Up | 66.7% (1 run) | 100% | no interval (1 run) |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| All (4 trials in the paper) |"), std::string::npos) << md;
  EXPECT_NE(md.find("## Lifts: errors (mm)\n\n| Method | arc mean | arc mean paper | arc mean "
                    "verdict | arc max |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| A | 1.20 (1 run) | 1.50 | no interval (1 run) | no runs | 4.00 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("\nVerdicts over the cells of the lift tables: "), std::string::npos) << md;
  EXPECT_EQ(cells.cells().front().table, "t1");
  EXPECT_EQ(cells.cells().back().table, "t2");
  EXPECT_EQ(cells.cells().back().quantity, "arc_error_max_mm");

  ReportCells none;
  EXPECT_EQ(decision_tables_section(spec, {}, none), "## Lift tables\n\nNo lift runs.\n");
  EXPECT_TRUE(none.cells().empty());
}

TEST(DecisionTables, GiveTheRunTablesReferenceRowsForRunsOfTheirTask) {
  TempDir dir;
  const DecisionTablesSpec spec = read_spec(dir, kSpec);
  const std::vector<ReferenceRow> rows = reference_rows(spec);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].label, "paper: a");
  EXPECT_EQ(rows[0].success, "3 of 4");
  EXPECT_EQ(rows[0].decision, "75%");  // up's 1.0 three times, down's 0.0 once
  EXPECT_EQ(rows[0].errors,
            (std::map<std::string, std::string>{{"arc_error_mean_mm", "1.50 / 4.00"}}));
  RunSummary lift, other;
  lift.settings["environment.type"] = "lift";
  other.settings["environment.type"] = "push";
  EXPECT_TRUE(reference_rows_apply({other, lift}, spec));
  EXPECT_FALSE(reference_rows_apply({other}, spec));
}

// Numbers for a label the tables do not have, or without one they have, are refused at
// their place in the file.
TEST(DecisionTables, NumbersMustBeForTheSpecsLabelsAndErrors) {
  TempDir dir;
  auto error_of = [&](const std::string& from, const std::string& to) {
    std::string text = kSpec;
    text.replace(text.find(from), from.size(), to);
    return config_error_of([&] { read_spec(dir, text); });
  };
  const std::string file = dir.file("spec.yaml");
  EXPECT_EQ(error_of("decision_match: {up: 1.0, down: 0.0}", "decision_match: {up: 1.0}"),
            file +
                ":21:23: decision_tables.columns[0].decision_match: no value for the label "
                "'down'");
  EXPECT_EQ(error_of("expected: {up: 3, down: 1}", "expected: {up: 3, down: 1, side: 2}"),
            file + ":12:30: decision_tables.expected.side: not one of the labels (up, down)");
  EXPECT_EQ(error_of("arc_error_max_mm: 4.0", "arc_eror_max_mm: 4.0"),
            file +
                ":24:15: decision_tables.columns[0].errors: no value for the error metric "
                "'arc_error_max_mm'");
}

}  // namespace
}  // namespace corrmp
