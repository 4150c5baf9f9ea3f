// Which robot a table-top task moves its gripper with: `floating` (a
// kinematic gripper moved directly) or `dual_arm` (a gripper carried by one
// arm of the dual-arm torso: DualArmParams's fields beside `type` and `arm`).
#pragma once

#include <string>

#include "core/config/field_rule.hpp"
#include "sim/robot/dual_arm.hpp"

namespace corrmp {

struct RobotParams {
  std::string type = "floating";
  std::string arm = "right";
  DualArmParams dual_arm;

  bool on_arms() const { return type == "dual_arm"; }
  Arm driving_arm() const { return arm == "left" ? Arm::left : Arm::right; }

  template <class Fields>
  void describe(Fields& f) {
    f("type", type,
      "floating: a kinematic gripper moved directly; dual_arm: a gripper carried by an arm of "
      "the dual-arm torso (IK with a fixed orientation, joint control)",
      one_of({"floating", "dual_arm"}));
    if (!on_arms()) return;
    f("arm", arm, "the arm carrying the gripper; the other holds its home pose",
      one_of({"left", "right"}));
    dual_arm.describe(f);
  }
};

}  // namespace corrmp
