// A reference's tables of a task with decisions, our runs beside its numbers:
// per expected label, the decisions chosen, the decision match and the task
// success; then the prediction errors; one column per experiment (a method),
// each cell the mean across runs with its 95% interval, the reference's
// number and a verdict. Which experiments, labels, errors and numbers, and
// the tables' titles, are data (DecisionTablesSpec, read from YAML); the
// same numbers also give the rows `report --paper` appends to the run table.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/config/config_node.hpp"
#include "core/config/field_rule.hpp"
#include "report/reference_cells.hpp"
#include "report/run_report.hpp"

namespace corrmp {

// A segment's error metrics, a column each in the error table.
struct ErrorColumns {
  std::string heading;    // "<heading> mean" and "<heading> max"
  std::string mean, max;  // metric names
  std::string unit;       // the errors' unit, in the run table's heading

  template <class Fields>
  void describe(Fields& f) {
    f("heading", heading, "the columns' heading, before 'mean' and 'max'", required());
    f("mean", mean, "the mean error's metric", required());
    f("max", max, "the largest error's metric", required());
    f("unit", unit, "the errors' unit, shown in the run table's heading");
  }
};

// The reference's numbers for one experiment's runs.
struct ReferenceColumn {
  std::string experiment;
  std::string key;      // names the row appended to the run table (shared by equal numbers)
  std::string heading;  // the column's heading in the tables
  int task_successes = 0;
  std::map<std::string, double> decision_match, task_success_rate;
  std::map<std::string, std::string> action_choice;
  std::map<std::string, double> errors;

  template <class Fields>
  void describe(Fields& f) {
    f("experiment", experiment, "the experiment whose runs fill the column", required());
    f("key", key, "the name of the reference's row in the run table", required());
    f("heading", heading, "the column's heading", required());
    f("task_successes", task_successes, "the reference's successful trials", at_least(0));
    f("decision_match", decision_match, "per label, the reference's decision match rate",
      in_range(0.0, 1.0));
    f("task_success_rate", task_success_rate, "per label, the reference's task success rate",
      in_range(0.0, 1.0));
    f("action_choice", action_choice, "per label, the reference's action choice as printed");
    f("errors", errors, "per error metric, the reference's value", at_least(0.0));
  }
};

struct DecisionTablesSpec {
  std::string environment;                     // the task (environment type) the numbers are of
  std::string decision_table, decision_title;  // report.csv's table name and the heading
  std::string error_table, error_title;
  std::string column_kind;  // what a column is (the error table's first heading)
  std::string verdicts_of;  // the tables the verdict count is over, as the reference names them
  std::string absent_title, absent_text;  // the section when no column has runs
  std::vector<PrintedLabel> labels;       // the expected labels, in table order
  std::map<std::string, int> expected;    // per label, the reference's trials expecting it
  std::vector<ErrorColumns> errors;
  std::vector<ReferenceColumn> columns;
  // Half the last digit the reference prints its rates and errors to: its
  // value stands for anything within it.
  double rate_rounding = 0.0, error_rounding = 0.0;

  template <class Fields>
  void describe(Fields& f) {
    f("environment", environment, "the task (environment type) the numbers are of", required());
    f("decision_table", decision_table, "report.csv's name of the decision tables", required());
    f("decision_title", decision_title, "the decision tables' heading", required());
    f("error_table", error_table, "report.csv's name of the error table", required());
    f("error_title", error_title, "the error table's heading", required());
    f("column_kind", column_kind, "what a column is (the error table's first heading)", required());
    f("verdicts_of", verdicts_of, "the tables the verdicts are counted over", required());
    f("absent_title", absent_title, "the section's heading without runs", required());
    f("absent_text", absent_text, "the section's text without runs", required());
    f("labels", labels, "the expected labels in table order", required());
    f("expected", expected, "per label, the reference's trials expecting it", at_least(0));
    f("errors", errors, "the error table's columns", required());
    f("columns", columns, "one column per experiment", required());
    f("rate_rounding", rate_rounding, "half the last printed digit of a rate", at_least(0.0));
    f("error_rounding", error_rounding, "half the last printed digit of an error", at_least(0.0));
  }
};

// Throws ConfigError, at `node` (the spec as read) and its key path under
// `path`, when a column's or the expected counts' labels are not the spec's
// labels, or a column lacks an error metric or names one the spec does not.
void check_decision_tables(const DecisionTablesSpec& spec, const ConfigNode& node,
                           const std::string& path);

// The experiments of the columns, in order.
std::vector<std::string> column_experiments(const DecisionTablesSpec& spec);

// The reference's trials: the expected counts summed.
int reference_trials(const DecisionTablesSpec& spec);

// The tables (Markdown, from its "## " heading), their cells added to
// `cells`, then the count of verdicts; the absent section when no column's
// experiment has runs.
std::string decision_tables_section(const DecisionTablesSpec& spec, const RunsOf& runs_of,
                                    ReportCells& cells);

// The run table's rows of the reference: per column, its task successes of
// its trials, its decision match over all trials (the per-label rates
// weighted by the expected counts) and its errors; columns sharing a key
// (the same numbers for two experiments) share the first one's row.
// The error columns those rows fill, with the reference's headings.
std::vector<ErrorMetric> reference_columns(const DecisionTablesSpec& spec);
std::vector<ReferenceRow> reference_rows(const DecisionTablesSpec& spec);

// Whether some run is of the spec's task (environment.type).
bool reference_rows_apply(const std::vector<RunSummary>& runs, const DecisionTablesSpec& spec);

}  // namespace corrmp
