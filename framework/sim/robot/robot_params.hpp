// A task's `robot:` section: what moves its grippers. `floating`: grippers
// moved directly where they are commanded; `dual_arm`: grippers carried by the
// dual-arm torso's tools through DualArm (DualArmParams's fields beside `type`,
// `arm` and `unseen_links`; declared for both types so that every field is
// documented and one config can switch the type).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/config/config_error.hpp"
#include "core/config/field_rule.hpp"
#include "core/parameter_error.hpp"
#include "sim/robot/dual_arm.hpp"

namespace corrmp {

struct RobotParams {
  std::string type = "floating";
  std::string arm = "right";
  DualArmParams dual_arm;
  // Links a task's camera does not draw: it sits in the head.
  std::vector<std::string> unseen_links{"torso", "head"};

  bool on_arms() const { return type == "dual_arm"; }
  Arm driving_arm() const { return arm == "left" ? Arm::left : Arm::right; }

  template <class Fields>
  void describe(Fields& f) {
    f("type", type,
      "floating: a kinematic gripper moved directly; dual_arm: a gripper carried by an arm of "
      "the dual-arm torso (IK with a fixed orientation, joint control)",
      one_of({"floating", "dual_arm"}));
    f("arm", arm,
      "the arm carrying the gripper of a one-gripper task; the other holds its home pose",
      one_of({"left", "right"}));
    dual_arm.describe(f);
    f("unseen_links", unseen_links, "robot links the task's camera does not draw");
  }
};

// The section's robot, for a task's world with tick `time_step` (s). A robot
// that cannot be built (a missing URDF, a bad home) is a ParameterError naming
// the `robot` key.
inline std::unique_ptr<DualArm> build_robot(const DualArmParams& params, double time_step) {
  try {
    return std::make_unique<DualArm>(params, time_step);
  } catch (const ConfigError& e) {
    throw ParameterError("robot", e.what());
  }
}

}  // namespace corrmp
