#include "sim/robot/multibody_layout.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "test_arms.hpp"

namespace corrmp {
namespace {

TEST(MultibodyLayout, OneBodyPerMovableJointWithFixedLinksMerged) {
  const RobotModel model = test::three_joint_arm();
  const MultibodyLayout layout = make_multibody_layout(model);
  ASSERT_EQ(layout.bodies.size(), 4u);
  EXPECT_EQ(layout.movable_joints, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(layout.bodies[2].parent, 1);
  EXPECT_EQ(layout.bodies[3].link, "link3");
  // The massless tool frame rides on link3's body at the fixed joint's origin.
  EXPECT_EQ(layout.links[4].body, 3);
  EXPECT_TRUE(layout.links[4].in_body.isApprox(model.joints[3].origin, 1e-15));
  EXPECT_DOUBLE_EQ(layout.bodies[3].mass, 0.5);
}

TEST(MultibodyLayout, RotatedInertiaBecomesPrincipalAxesAtTheCentreOfMass) {
  const RobotModel model = test::three_joint_arm();
  const LayoutBody body = make_multibody_layout(model).bodies[2];
  const RobotLink& link = model.links[2];
  EXPECT_TRUE(body.com.translation().isApprox(link.inertial_origin.translation(), 1e-15));
  // The same inertia in the link frame, now diagonal in the body's frame.
  const Eigen::Matrix3d in_link =
      link.inertial_origin.linear() * link.inertia * link.inertial_origin.linear().transpose();
  const Eigen::Matrix3d rebuilt =
      body.com.linear() * body.principal_inertia.asDiagonal() * body.com.linear().transpose();
  EXPECT_TRUE(rebuilt.isApprox(in_link, 1e-12));
  EXPECT_NEAR(body.com.linear().determinant(), 1.0, 1e-12);
}

TEST(MultibodyLayout, MergedMassesCombineByTheParallelAxisTheorem) {
  RobotModel model = test::three_joint_arm();
  model.links[4].mass = 1.0;  // the tool, 0.2 m beyond link3's origin
  model.links[4].inertial_origin = Eigen::Isometry3d::Identity();
  const LayoutBody body = make_multibody_layout(model).bodies[3];
  EXPECT_DOUBLE_EQ(body.mass, 1.5);
  const Eigen::Vector3d tool = model.joints[3].origin.translation();
  const Eigen::Vector3d expected = (0.5 * Eigen::Vector3d(0, 0, 0.1) + 1.0 * tool) / 1.5;
  EXPECT_TRUE(body.com.translation().isApprox(expected, 1e-12));
  const double trace = model.links[3].inertia.trace() +
                       0.5 * 2 * (Eigen::Vector3d(0, 0, 0.1) - expected).squaredNorm() +
                       1.0 * 2 * (tool - expected).squaredNorm();
  EXPECT_NEAR(body.principal_inertia.sum(), trace, 1e-12);
}

TEST(MultibodyLayout, MasslessMovableLinkGetsTheSmallestMass) {
  RobotModel model = test::three_joint_arm();
  model.links[3].mass = 0.0;
  model.links[3].inertia.setZero();
  const LayoutBody body = make_multibody_layout(model).bodies[3];
  EXPECT_EQ(body.mass, kMinBodyMass);
  EXPECT_EQ(body.principal_inertia, Eigen::Vector3d::Constant(kMinPrincipalInertia));
}

TEST(MultibodyLayout, MalformedModelsNameTheProblem) {
  RobotModel zero_axis = test::three_joint_arm();
  zero_axis.joints[1].axis.setZero();
  EXPECT_THROW(make_multibody_layout(zero_axis), std::invalid_argument);
  RobotModel orphan = test::three_joint_arm();
  orphan.joints[2].parent = "nowhere";
  try {
    make_multibody_layout(orphan);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "robot 'three_joint_arm': joint 'joint3': parent link 'nowhere' is unknown or not "
                 "reached from the root");
  }
}

}  // namespace
}  // namespace corrmp
