// The share of each experiment's trials lost to each failure category its task declares
// (TaskDeclaration::failure_categories), from the runs' failures_<category> counts: one row per
// experiment (its trials pooled over its runs), one column per category any of them declares,
// then the failures in no declared category. Every cell is also a row of report.csv.
#pragma once

#include <string>
#include <vector>

#include "report/reference_cells.hpp"

namespace corrmp {

// The section (Markdown, from its "## " heading) over the experiments in `order` that have runs
// in `runs_of` with a declared task, their cells added to `cells` (table "failure_shares", row:
// the experiment, group: the category, "failed" or "other").
std::string failure_share_section(const RunsOf& runs_of, const std::vector<std::string>& order,
                                  ReportCells& cells);

}  // namespace corrmp
