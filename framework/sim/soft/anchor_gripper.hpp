// A parallel two-finger gripper for the rope task (paper, Section IV-C): a palm
// and two fingers that are drawn but do not collide with the rope; grasping
// anchors the rope nodes inside the finger gap to the gripper (so closing
// doubles as the enclose test: 0 anchored nodes = missed enclose), opening
// ramps the anchors' influence to zero (a sudden release under tension makes
// the rope tunnel through itself). Its position is the finger mid-point (the
// centre of the gap); its orientation is fixed.
//
// Gripper frame: z = approach (the fingers point along +z from the palm),
// x = closing axis, y = finger width.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/render/render_scene.hpp"
#include "sim/soft/rope.hpp"

class btRigidBody;
class btCollisionShape;

namespace corrmp {

struct AnchorGripperParams {
  double opening = 0.04;
  double finger_length = 0.05;
  double finger_width = 0.02;
  double finger_thickness = 0.01;
  double palm_thickness = 0.015;
  double max_speed = 0.15;
  double release_time = 0.3;
  std::vector<double> colour{0.25, 0.25, 0.3};

  template <class Fields>
  void describe(Fields& f) {
    f("opening", opening, "gap between open fingers (m)", positive());
    f("finger_length", finger_length, "finger length along the approach axis (m)", positive());
    f("finger_width", finger_width, "finger width across the closing axis (m)", positive());
    f("finger_thickness", finger_thickness, "finger thickness along the closing axis (m)",
      positive());
    f("palm_thickness", palm_thickness, "palm thickness along the approach axis (m)", positive());
    f("max_speed", max_speed, "largest speed when tracking waypoints (m/s)", in_range(0.005, 10.0));
    f("release_time", release_time, "time over which opening ramps the anchors out (s)",
      FieldRule{}.above(0.0).at_most(10.0));
    f("colour", colour, "RGB in [0, 1]", size_is(3).at_least(0.0).at_most(1.0));
  }
};

class AnchorGripper {
 public:
  // `orientation` maps gripper-frame directions to the world.
  AnchorGripper(Rope& rope, const AnchorGripperParams& params, const Eigen::Matrix3d& orientation,
                const Eigen::Vector3d& position);
  ~AnchorGripper();
  AnchorGripper(const AnchorGripper&) = delete;
  AnchorGripper& operator=(const AnchorGripper&) = delete;

  Eigen::Vector3d position() const { return position_; }
  const Eigen::Matrix3d& orientation() const { return orientation_; }
  const AnchorGripperParams& params() const { return params_; }

  // Puts the gripper at `position` for the coming physics step (moving the
  // anchored nodes with it) and advances a release in progress by one tick.
  void tick_to(const Eigen::Vector3d& position);
  // Teleports the gripper (no velocity): for set-up before a trial.
  void place(const Eigen::Vector3d& position);

  // Anchors the rope nodes inside the finger gap; returns how many (0 = missed).
  int close();
  // Starts the gradual release of the anchored nodes.
  void open();
  bool closed() const { return closed_; }
  int anchored() const;    // anchors of this gripper still acting
  bool releasing() const;  // open, with anchors still ramping out

  std::vector<int> nodes_in_gap() const;
  // A finger within a rope radius of the rope's surface while no node is in the gap.
  bool near_miss() const;

  void add_to(RenderScene& scene) const;

 private:
  Eigen::Vector3d local(const Eigen::Vector3d& world) const;
  void set_body(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);
  void remove_anchors();

  Rope& rope_;
  AnchorGripperParams params_;
  Eigen::Matrix3d orientation_;
  Eigen::Vector3d position_;
  bool closed_ = false;
  double influence_ = 1.0;
  std::unique_ptr<btCollisionShape> shape_;
  std::unique_ptr<btRigidBody> body_;
};

}  // namespace corrmp
