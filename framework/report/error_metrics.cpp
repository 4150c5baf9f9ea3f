// Trajectory error metrics by their declarations (error_metrics.hpp).
#include "report/error_metrics.hpp"

#include <algorithm>

namespace corrmp {

namespace {

// The run's metric declared as `statistic` under `heading`, or "".
std::string statistic_under(const RunSummary& run, const std::string& heading,
                            const std::string& statistic) {
  for (const auto& name : run.metric_order) {
    const auto it = run.declarations.find(name);
    if (it != run.declarations.end() && it->second.heading == heading &&
        it->second.statistic == statistic) {
      return name;
    }
  }
  return "";
}

}  // namespace

std::vector<ErrorMetric> error_metrics(const std::vector<RunSummary>& runs) {
  std::vector<ErrorMetric> errors;
  for (const auto& run : runs) {
    for (const auto& name : run.metric_order) {
      const auto declaration = run.declarations.find(name);
      if (declaration == run.declarations.end() || declaration->second.heading.empty() ||
          declaration->second.statistic != "mean") {
        continue;
      }
      const std::string& heading = declaration->second.heading;
      const auto known = std::find_if(errors.begin(), errors.end(),
                                      [&](const ErrorMetric& e) { return e.mean == name; });
      if (known == errors.end()) {
        errors.push_back({name, statistic_under(run, heading, "max"), heading});
      } else if (known->max.empty()) {  // the first run recording it had no max
        known->max = statistic_under(run, heading, "max");
      }
    }
  }
  return errors;
}

}  // namespace corrmp
