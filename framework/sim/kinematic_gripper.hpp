// A two-finger parallel gripper of kinematic bodies (a palm and two fingers)
// whose pose is set every tick, moving towards each waypoint in turn at a
// bounded speed, one physics step per tick (Bullet derives a kinematic body's
// velocity from its last pose, so pushed objects feel a smooth motion).
#pragma once

#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/bullet_world.hpp"
#include "sim/gripper.hpp"

namespace corrmp {

struct GripperParams {
  std::vector<double> finger_size{0.015, 0.03, 0.05};  // x, y, z (m)
  std::vector<double> palm_size{0.06, 0.03, 0.015};
  double opening = 0.04;    // gap between open fingers (m); closed fingers touch
  double max_speed = 0.05;  // m/s: slow enough that a pushed object stops within 1 mm
  std::vector<double> colour{0.25, 0.25, 0.3};

  template <class Fields>
  void describe(Fields& f) {
    f("finger_size", finger_size, "finger box [x, y, z] (m); fingers close along x",
      size_is(3).above(0.0));
    f("palm_size", palm_size, "palm box [x, y, z] (m)", size_is(3).above(0.0));
    f("opening", opening, "gap between open fingers (m)", at_least(0.0));
    f("max_speed", max_speed, "largest tool speed (m/s)", in_range(0.005, 10.0));
    f("colour", colour, "RGB in [0, 1]", size_is(3).at_least(0.0).at_most(1.0));
  }
};

class KinematicGripper : public Gripper {
 public:
  KinematicGripper(BulletWorld& world, const GripperParams& params, const Eigen::Vector3d& start);

  Eigen::Vector3d position() const override { return position_; }
  void set_closed(bool closed) override;
  // Puts the gripper's bodies at `position` (the tool centre point) at once.
  void place(const Eigen::Vector3d& position);
  TrackingResult follow(const Eigen::MatrixXd& waypoints,
                        const std::function<std::string()>& check) override;

  const std::vector<int>& bodies() const { return bodies_; }

 private:
  void place_bodies();

  BulletWorld& world_;
  GripperParams params_;
  Eigen::Vector3d position_;
  bool closed_ = true;
  std::vector<int> bodies_;  // palm, left finger, right finger
};

}  // namespace corrmp
