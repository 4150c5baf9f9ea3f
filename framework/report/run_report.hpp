// Reports over recorded runs: one row per run with its task success, decision
// match and each trajectory error it declared, and the
// settings that vary between runs of the same experiment, so a sweep or a
// comparison with the baseline reads as one table (Markdown or CSV).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "report/error_metrics.hpp"
#include "report/run_summaries.hpp"

namespace corrmp {

// A row of reference numbers (a publication's) below the runs of the Markdown table.
struct ReferenceRow {
  std::string label;  // in the experiment column
  std::string success, decision;
  std::map<std::string, std::string> errors;  // by the error column's mean metric
};

struct ReportFormat {
  std::vector<std::string> extra_metrics;    // more metric columns, by name
  std::vector<ReferenceRow> reference_rows;  // appended to the Markdown table
  // The error columns the reference rows fill, added after the runs' own when no run recorded
  // them.
  std::vector<ErrorMetric> reference_columns;
  // Each run's status (completed, failed, ...) in a column of the Markdown
  // table, for report --all; the CSV always has one.
  bool status_column = false;
};

std::string report_markdown(const std::vector<RunSummary>& runs, const ReportFormat& format);
std::string report_csv(const std::vector<RunSummary>& runs, const ReportFormat& format);

}  // namespace corrmp
