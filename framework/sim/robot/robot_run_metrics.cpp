// The robot's trial details and run metrics (robot_run_metrics.hpp).
#include "sim/robot/robot_run_metrics.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace corrmp {

namespace {

constexpr const char* kTrackingError = "max_tracking_error";
constexpr const char* kSolves = "ik_solves";
constexpr const char* kFailures = "ik_failures";

}  // namespace

void add_robot_details(const DualArm& robot, std::map<std::string, double>& details) {
  details[kTrackingError] = robot.max_tracking_error();
  details[kSolves] = static_cast<double>(robot.ik_stats().solves);
  details[kFailures] = static_cast<double>(robot.ik_stats().failures);
}

std::vector<Metric> robot_run_metrics(const std::vector<EvaluatedTrial>& trials) {
  double solves = 0.0, failures = 0.0, error_sum = 0.0, error_max = 0.0;
  int measured = 0;
  for (const EvaluatedTrial& trial : trials) {
    const auto error = trial.details.find(kTrackingError);
    const auto solved = trial.details.find(kSolves);
    const auto failed = trial.details.find(kFailures);
    if (error == trial.details.end() || solved == trial.details.end() ||
        failed == trial.details.end()) {
      continue;
    }
    ++measured;
    solves += solved->second;
    failures += failed->second;
    error_sum += error->second;
    error_max = std::max(error_max, error->second);
  }
  std::vector<Metric> metrics;
  if (measured == 0) return metrics;
  metrics.push_back({"ik_solves", solves, count_metric(Better::neither)});
  if (solves > 0) {
    metrics.push_back({"ik_success_rate", 1.0 - failures / solves, rate_metric(Better::higher)});
  }
  const std::string heading = "joint tracking error mean / max (rad)";
  metrics.push_back({"joint_tracking_error_mean_rad", error_sum / measured,
                     error_statistic("rad", heading, "mean")});
  metrics.push_back(
      {"joint_tracking_error_max_rad", error_max, error_statistic("rad", heading, "max")});
  return metrics;
}

std::string ik_time_log_line(const IkSolveTimes& times, const std::string& label) {
  if (times.solves() == 0) return "";
  return fmt::format("IK time ({}): {} solves, median {:.1f} us, mean {:.1f} us per solve", label,
                     times.solves(), 1e6 * times.median_seconds(), 1e6 * times.mean_seconds());
}

}  // namespace corrmp
