// The motion every gripper makes through Cartesian waypoints: a commanded
// point moved straight towards each waypoint in turn by at most one step per
// tick, the effector brought to it every tick.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

#include "sim/gripper.hpp"

namespace corrmp {

// Moves `commanded` through the waypoints (rows x, y, z) by at most
// `step_length` per tick; each tick calls `tick` once `commanded` holds the
// tick's point, and stops the motion as a failure when it returns a non-empty
// string. A non-finite waypoint stops it too; waypoints without 3 columns
// throw std::invalid_argument. Each time `commanded` reaches a waypoint (after
// that tick, or at once when it is already there), `effector` gives the
// effector's position for TrackingResult::reached; it must not change the world.
TrackingResult step_through_waypoints(const Eigen::MatrixXd& waypoints, double step_length,
                                      Eigen::Vector3d& commanded,
                                      const std::function<std::string()>& tick,
                                      const std::function<Eigen::Vector3d()>& effector);

}  // namespace corrmp
