#include "sim/robot/kdl_chain.hpp"

#include <gtest/gtest.h>

#include <kdl/chainfksolverpos_recursive.hpp>

#include "config/test_files.hpp"
#include "core/seeds.hpp"
#include "sim/robot/shipped_robot.hpp"

namespace corrmp {
namespace {

using testing::kShippedRobot;

// The tip pose composed joint by joint: origin, then the motion along the axis
// given in the child frame.
Eigen::Isometry3d pose_by_hand(const RobotModel& model, const std::vector<int>& chain,
                               const std::vector<double>& q) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  size_t next = 0;
  for (int index : chain) {
    const RobotJoint& joint = model.joints[index];
    pose = pose * joint.origin;
    if (joint.type == JointType::revolute) pose.rotate(Eigen::AngleAxisd(q[next++], joint.axis));
    if (joint.type == JointType::prismatic) pose.translate(q[next++] * joint.axis);
  }
  return pose;
}

void expect_chain_matches_model(const RobotModel& model, const std::string& base,
                                const std::string& tip) {
  const KDL::Chain chain = kdl_chain(model, base, tip);
  const std::vector<int> joints = model.chain(base, tip);
  ASSERT_EQ(chain.getNrOfSegments(), joints.size());
  KDL::ChainFkSolverPos_recursive fk(chain);
  Rng rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> q;
    for (int index : joints) {
      const RobotJoint& joint = model.joints[index];
      if (joint.type != JointType::fixed) q.push_back(rng.uniform(joint.lower, joint.upper));
    }
    ASSERT_EQ(chain.getNrOfJoints(), q.size());
    KDL::JntArray kdl_q(q.size());
    for (size_t j = 0; j < q.size(); ++j) kdl_q(j) = q[j];
    KDL::Frame frame;
    ASSERT_GE(fk.JntToCart(kdl_q, frame), 0);
    const Eigen::Isometry3d expected = pose_by_hand(model, joints, q);
    for (int r = 0; r < 3; ++r) {
      EXPECT_NEAR(frame.p(r), expected.translation()(r), 1e-12) << tip;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(frame.M(r, c), expected.linear()(r, c), 1e-12) << tip;
    }
  }
}

TEST(KdlChain, ShippedArmsMatchTheModelComposedByHand) {
  const RobotModel model = load_robot_model(kShippedRobot);
  expect_chain_matches_model(model, "base", "left_tool");
  expect_chain_matches_model(model, "base", "right_tool");
  expect_chain_matches_model(model, "torso", "right_link_4");
}

TEST(KdlChain, TiltedAxesAndPrismaticJointsMatchTheModel) {
  const testing::TempDir dir;
  const std::string path =
      dir.write("robot.urdf",
                "<robot name='r'><link name='a'/><link name='b'/><link name='c'/><link name='d'/>"
                "<joint name='j1' type='revolute'><parent link='a'/><child link='b'/>"
                "<origin xyz='0.1 0.2 0.3' rpy='0.3 -0.4 0.5'/><axis xyz='1 2 -1'/>"
                "<limit lower='-2' upper='2' velocity='1' effort='1'/></joint>"
                "<joint name='j2' type='prismatic'><parent link='b'/><child link='c'/>"
                "<origin xyz='0 0.4 0' rpy='1.0 0 0.2'/><axis xyz='0 1 1'/>"
                "<limit lower='-0.5' upper='0.5' velocity='1' effort='1'/></joint>"
                "<joint name='f' type='fixed'><parent link='c'/><child link='d'/>"
                "<origin xyz='0.05 0 0.1' rpy='0 1.2 0'/></joint></robot>");
  expect_chain_matches_model(load_robot_model(path), "a", "d");
}

TEST(KdlChain, HeadCameraLooksForwardAndDownAtTheTable) {
  const RobotModel model = load_robot_model(kShippedRobot);
  const KDL::Chain chain = kdl_chain(model, "base", "head_camera");
  EXPECT_EQ(chain.getNrOfJoints(), 0u);
  const Eigen::Isometry3d camera = pose_by_hand(model, model.chain("base", "head_camera"), {});
  const Eigen::Vector3d view = camera.linear().col(2);
  EXPECT_GT(view.x(), 0.5);
  EXPECT_LT(view.z(), -0.7);
  EXPECT_NEAR(view.y(), 0.0, 1e-6);                     // rpy written to 6 decimals
  EXPECT_NEAR(camera.linear().col(0).y(), -1.0, 1e-6);  // image right is the robot's right
}

}  // namespace
}  // namespace corrmp
