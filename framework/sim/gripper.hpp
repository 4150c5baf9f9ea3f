// A gripper moved along Cartesian waypoints (the paper's execution: a
// predicted Cartesian trajectory tracked by the robot, Section IV-A). Behind
// this interface so that an IK-driven arm can take the kinematic gripper's place.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

namespace corrmp {

struct TrackingResult {
  bool ok = true;
  std::string failure;  // why tracking stopped early
  int ticks = 0;
  // Per waypoint reached, in order: where the effector was when the command
  // reached it (rows x, y, z); rows stop where tracking stopped.
  Eigen::MatrixXd reached;
};

class Gripper {
 public:
  virtual ~Gripper() = default;
  // The tool centre point (between the fingers) in the world frame.
  virtual Eigen::Vector3d position() const = 0;
  virtual void set_closed(bool closed) = 0;
  // Moves through the waypoints (rows x, y, z), stepping the world every tick.
  // `check` runs after each tick; a non-empty string stops the motion as a failure.
  // TrackingResult::reached holds the position() at each waypoint reached.
  virtual TrackingResult follow(const Eigen::MatrixXd& waypoints,
                                const std::function<std::string()>& check) = 0;
};

}  // namespace corrmp
