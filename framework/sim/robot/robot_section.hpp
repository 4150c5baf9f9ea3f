// What carries a task's grippers, as an environment's `robot:` section:
// "floating" (the grippers go where they are commanded) or "dual_arm" (the
// dual-arm torso's tools, executed through DualArm; the section's other keys
// are DualArmParams').
#pragma once

#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/robot/dual_arm.hpp"

namespace corrmp {

struct RobotSection {
  std::string type = "floating";
  DualArmParams arm;
  // The head camera sits in the head: the torso and head are not drawn.
  std::vector<std::string> unseen_links{"torso", "head"};

  bool on_arms() const { return type == "dual_arm"; }

  template <class Fields>
  void describe(Fields& f) {
    f("type", type, "floating grippers or the dual-arm torso's tools",
      one_of({"floating", "dual_arm"}));
    arm.describe(f);
    f("unseen_links", unseen_links, "robot links the task's camera does not draw (dual_arm)");
  }
};

}  // namespace corrmp
