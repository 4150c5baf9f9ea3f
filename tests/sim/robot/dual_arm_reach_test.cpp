// Tests of DualArm's reach check and of links allowed to touch: reach() tells
// the category track() would return without moving the arms; links named in
// touching_links must exist.
#include <gtest/gtest.h>

#include "core/config/config_error.hpp"
#include "sim/robot/dual_arm.hpp"

namespace corrmp {
namespace {

TEST(DualArmReach, TellsWhetherTargetsAreReachedWithoutMoving) {
  DualArm arm(DualArmParams{}, 1.0 / 240.0);
  const Eigen::Vector3d left = arm.tool_position(Arm::left);
  const Eigen::Vector3d right = arm.tool_position(Arm::right);
  EXPECT_EQ(arm.reach(left + Eigen::Vector3d(0.02, 0.0, 0.0), right), "");
  const std::string far = arm.reach(left, Eigen::Vector3d(2.0, 0.0, 0.3));
  EXPECT_EQ(far.rfind("out of reach: right arm", 0), 0u) << far;
  EXPECT_EQ(arm.tool_position(Arm::left), left);
  EXPECT_EQ(arm.tool_position(Arm::right), right);
  EXPECT_EQ(arm.track(left, Eigen::Vector3d(2.0, 0.0, 0.3)), "out of reach");
}

TEST(DualArmReach, TouchingLinksMustBeTheRobots) {
  DualArmParams params;
  params.touching_links = {"left_finger_1", "no_such_link"};
  EXPECT_THROW(DualArm(params, 1.0 / 240.0), ConfigError);
}

}  // namespace
}  // namespace corrmp
