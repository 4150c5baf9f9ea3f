// Bounded-speed stepping through waypoints.
#include "sim/waypoint_stepping.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

namespace corrmp {

TrackingResult step_through_waypoints(const Eigen::MatrixXd& waypoints, double step_length,
                                      Eigen::Vector3d& commanded,
                                      const std::function<std::string()>& tick,
                                      const std::function<Eigen::Vector3d()>& effector) {
  TrackingResult result;
  if (waypoints.cols() != 3) {
    throw std::invalid_argument(
        fmt::format("gripper waypoints need 3 columns (x, y, z), got {}", waypoints.cols()));
  }
  result.reached.resize(waypoints.rows(), 3);
  const auto stop = [&](Eigen::Index reached, std::string failure) {
    result.ok = false;
    result.failure = std::move(failure);
    result.reached.conservativeResize(reached, 3);
    return result;
  };
  for (Eigen::Index w = 0; w < waypoints.rows(); ++w) {
    const Eigen::Vector3d target = waypoints.row(w).transpose();
    if (!target.allFinite()) return stop(w, fmt::format("waypoint {} is not finite", w));
    while (true) {
      const Eigen::Vector3d to_go = target - commanded;
      const double distance = to_go.norm();
      if (distance < 1e-12) break;
      commanded = distance <= step_length ? target : commanded + to_go * (step_length / distance);
      ++result.ticks;
      std::string failure = tick();
      if (!failure.empty()) return stop(w, std::move(failure));
    }
    result.reached.row(w) = effector().transpose();
  }
  return result;
}

}  // namespace corrmp
