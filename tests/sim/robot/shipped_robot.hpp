// The robot the framework ships, for the tests that load it.
#pragma once

#include <string>

namespace corrmp::testing {

inline const std::string kShippedRobot =
    std::string(PROJECT_DIR) + "/assets/robots/dual_arm_torso.urdf";

}  // namespace corrmp::testing
