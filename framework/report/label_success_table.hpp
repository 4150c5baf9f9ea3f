// Task success per expected label for a reference without numbers: one column
// per experiment, each cell the mean success rate across runs with its 95%
// interval (over the runs expecting the label at least once), then the trials
// pooled over the runs. Which experiments and the labels' order are data.
#pragma once

#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "report/reference_cells.hpp"

namespace corrmp {

struct LabelSuccessSpec {
  std::string table;          // report.csv's name of the table
  std::string title, text;    // the section's heading and why there is no reference number
  std::string absent_text;    // the section's text when no experiment has runs
  std::string label_heading;  // the first column's heading
  std::vector<std::string> experiments;
  // For runs recorded without their task's declaration: the labels first in this order, then
  // any other the runs expected, alphabetically. Runs that declared an order use it.
  std::vector<std::string> labels;

  template <class Fields>
  void describe(Fields& f) {
    f("table", table, "report.csv's name of the table", required());
    f("title", title, "the section's heading", required());
    f("text", text, "why the reference has no number", required());
    f("absent_text", absent_text, "the section's text without runs", required());
    f("label_heading", label_heading, "the first column's heading", required());
    f("experiments", experiments, "one column per experiment", required());
    f("labels", labels, "the labels' order", required());
  }
};

// The section (Markdown, from its "## " heading), its cells added to `cells`.
std::string label_success_section(const LabelSuccessSpec& spec, const RunsOf& runs_of,
                                  ReportCells& cells);

}  // namespace corrmp
