// The trajectory errors among a run's metrics (docs/usage.md, "Where results go"; paper, Table II):
// the closed-loop <segment>_mp_error_mean_<unit> and _max_<unit> of a task's trials, and, for a run
// with no environment, the held-out demonstrations' <segment>_error_mean and _max (in the data's
// units). The run table and the comparison give each one a column.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/run_summaries.hpp"

namespace corrmp {

struct ErrorMetric {
  std::string mean, max;  // the metrics' names
  std::string heading;    // e.g. "cor-MP error mean / max (cm)"
};

/// The error whose mean is the metric `name`, if it is one.
std::optional<ErrorMetric> error_metric(const std::string& name);

/// Every error the runs recorded, in the order the first run recording it did (the task's order
/// of segments).
std::vector<ErrorMetric> error_metrics(const std::vector<RunSummary>& runs);

}  // namespace corrmp
