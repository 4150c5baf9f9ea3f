// The trajectory errors among a run's metrics (docs/usage.md, "Where results go"; paper, Table
// II): the statistics a run declared under one report heading (core/metric.hpp), such as the
// closed-loop <segment>_mp_error_mean_<unit> and _max_<unit> of a task's trials, or, for a run
// with no environment, the held-out demonstrations' <segment>_error_mean and _max. The run table
// and the comparison give each one a column.
#pragma once

#include <string>
#include <vector>

#include "report/run_summaries.hpp"

namespace corrmp {

struct ErrorMetric {
  std::string mean, max;  // the metrics' names ("" for a statistic the run did not record)
  std::string heading;    // e.g. "cor-MP error mean / max (cm)"
};

/// Every error the runs recorded, in the order the first run recording it did (the task's order
/// of segments): each heading under which a run declared a "mean" statistic, with the "max" the
/// run declared under it.
std::vector<ErrorMetric> error_metrics(const std::vector<RunSummary>& runs);

}  // namespace corrmp
