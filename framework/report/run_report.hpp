// Reports over recorded runs: one row per run with the paper's Table I and II
// figures (task success, decision match, cor-MP and post-MP errors) and the
// settings that vary between runs of the same experiment, so a sweep or a
// comparison with the baseline reads as one table (Markdown or CSV).
#pragma once

#include <string>
#include <vector>

#include "report/run_summaries.hpp"

namespace corrmp {

struct ReportFormat {
  std::vector<std::string> extra_metrics;  // more metric columns, by name
  std::string paper_tables;  // when set, the paper's PC, AE and Mono rows from this file
                             // (assets/paper/tables.yaml) are appended (Markdown only) if
                             // some run is of the task they are of (paper_rows_apply)
  // Each run's status (completed, failed, ...) in a column of the Markdown
  // table, for report --all; the CSV always has one.
  bool status_column = false;
};

/// The task (environment type) the paper's tables in this file are of; "" if they name none.
std::string paper_environment(const std::string& paper_tables);
/// True if some run is of that task (environment.type), or the tables name none.
bool paper_rows_apply(const std::vector<RunSummary>& runs, const std::string& paper_tables);

std::string report_markdown(const std::vector<RunSummary>& runs, const ReportFormat& format);
std::string report_csv(const std::vector<RunSummary>& runs, const ReportFormat& format);

}  // namespace corrmp
