// Trajectory error metrics by name (error_metrics.hpp).
#include "report/error_metrics.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace corrmp {

namespace {

const std::string kClosedLoopMean = "_mp_error_mean_";  // <segment>_mp_error_mean_<unit>
const std::string kHeldOutMean = "_error_mean";         // <segment>_error_mean

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

std::optional<ErrorMetric> error_metric(const std::string& name) {
  if (const auto at = name.find(kClosedLoopMean); at != std::string::npos && at > 0) {
    const std::string segment = name.substr(0, at), unit = name.substr(at + kClosedLoopMean.size());
    if (unit.empty()) return std::nullopt;
    return ErrorMetric{name, segment + "_mp_error_max_" + unit,
                       fmt::format("{}-MP error mean / max ({})", segment, unit)};
  }
  if (ends_with(name, kHeldOutMean) && name.size() > kHeldOutMean.size()) {
    const std::string segment = name.substr(0, name.size() - kHeldOutMean.size());
    return ErrorMetric{name, segment + "_error_max",
                       fmt::format("{} error mean / max (held-out)", segment)};
  }
  return std::nullopt;
}

std::vector<ErrorMetric> error_metrics(const std::vector<RunSummary>& runs) {
  std::vector<ErrorMetric> errors;
  for (const auto& run : runs) {
    for (const auto& name : run.metric_order) {
      const auto error = error_metric(name);
      if (!error) continue;
      const bool known = std::any_of(errors.begin(), errors.end(),
                                     [&](const ErrorMetric& e) { return e.mean == error->mean; });
      if (!known) errors.push_back(*error);
    }
  }
  return errors;
}

}  // namespace corrmp
