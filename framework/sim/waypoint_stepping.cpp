// Bounded-speed stepping through waypoints.
#include "sim/waypoint_stepping.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace corrmp {

TrackingResult step_through_waypoints(const Eigen::MatrixXd& waypoints, double step_length,
                                      Eigen::Vector3d& commanded,
                                      const std::function<std::string()>& tick) {
  TrackingResult result;
  if (waypoints.cols() != 3) {
    throw std::invalid_argument(
        fmt::format("gripper waypoints need 3 columns (x, y, z), got {}", waypoints.cols()));
  }
  for (Eigen::Index w = 0; w < waypoints.rows(); ++w) {
    const Eigen::Vector3d target = waypoints.row(w).transpose();
    if (!target.allFinite()) {
      result.ok = false;
      result.failure = fmt::format("waypoint {} is not finite", w);
      return result;
    }
    while (true) {
      const Eigen::Vector3d to_go = target - commanded;
      const double distance = to_go.norm();
      if (distance < 1e-12) break;
      commanded = distance <= step_length ? target : commanded + to_go * (step_length / distance);
      ++result.ticks;
      std::string failure = tick();
      if (!failure.empty()) {
        result.ok = false;
        result.failure = failure;
        return result;
      }
    }
  }
  return result;
}

}  // namespace corrmp
