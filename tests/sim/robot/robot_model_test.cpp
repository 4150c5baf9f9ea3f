#include "sim/robot/robot_model.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "sim/robot/shipped_robot.hpp"

namespace corrmp {
namespace {

using testing::config_error_of;
using testing::TempDir;

using testing::kShippedRobot;

std::string robot(const std::string& body) { return "<robot name='r'>" + body + "</robot>"; }

std::string revolute(const std::string& name, const std::string& parent, const std::string& child,
                     const std::string& extra) {
  return "<joint name='" + name + "' type='revolute'><parent link='" + parent + "'/><child link='" +
         child + "'/>" + extra + "</joint>";
}

const std::string kLimits = "<limit lower='-1' upper='1' velocity='1' effort='10'/>";

// The error loading `text` from a file gives, checked to start with the file's path.
std::string load_error(const TempDir& dir, const std::string& text) {
  const std::string path = dir.write("robot.urdf", text);
  const std::string message = config_error_of([&] { load_robot_model(path); });
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  return message;
}

TEST(RobotModel, MissingFileNamesThePath) {
  const TempDir dir;
  const std::string path = dir.file("absent.urdf");
  const std::string message = config_error_of([&] { load_robot_model(path); });
  EXPECT_EQ(message.rfind(path + ": cannot open for reading", 0), 0u) << message;
}

TEST(RobotModel, MalformedXmlIsReportedWithItsLine) {
  const TempDir dir;
  const std::string message = load_error(dir, "<robot name='r'>\n<link name='a'/\n</robot>");
  EXPECT_NE(message.find("malformed XML at line 2"), std::string::npos) << message;
}

TEST(RobotModel, UnknownJointTypeIsReported) {
  const TempDir dir;
  const std::string message =
      load_error(dir, robot("<link name='a'/><link name='b'/><joint name='j' type='hinge'>"
                            "<parent link='a'/><child link='b'/></joint>"));
  EXPECT_NE(message.find("invalid URDF: Joint [j] has no known type [hinge]"), std::string::npos)
      << message;
}

TEST(RobotModel, ContinuousAndFloatingJointsAreRejected) {
  const TempDir dir;
  for (const std::string type : {"continuous", "floating", "planar"}) {
    const std::string message =
        load_error(dir, robot("<link name='a'/><link name='b'/><joint name='j' type='" + type +
                              "'><parent link='a'/><child link='b'/>" + kLimits + "</joint>"));
    EXPECT_NE(message.find("joint 'j': " + type + " joints are not supported"), std::string::npos)
        << message;
  }
}

TEST(RobotModel, MovableJointWithoutLimitsIsReported) {
  const TempDir dir;
  const std::string message =
      load_error(dir, robot("<link name='a'/><link name='b'/>" + revolute("j", "a", "b", "")));
  EXPECT_NE(message.find("Joint [j] is of type REVOLUTE but it does not specify limits"),
            std::string::npos)
      << message;
}

TEST(RobotModel, EmptyLimitRangeAndZeroAxisAreReported) {
  const TempDir dir;
  EXPECT_NE(load_error(dir, robot("<link name='a'/><link name='b'/>" +
                                  revolute("j", "a", "b",
                                           "<limit lower='1' upper='1' velocity='1' "
                                           "effort='1'/>")))
                .find("joint 'j': lower limit 1.000000 is not below upper limit 1.000000"),
            std::string::npos);
  EXPECT_NE(load_error(dir, robot("<link name='a'/><link name='b'/>" +
                                  revolute("j", "a", "b", "<axis xyz='0 0 0'/>" + kLimits)))
                .find("joint 'j': zero axis"),
            std::string::npos);
}

TEST(RobotModel, MeshGeometryIsReported) {
  const TempDir dir;
  const std::string message = load_error(
      dir, robot("<link name='a'><collision><geometry><mesh filename='a.stl'/></geometry>"
                 "</collision></link>"));
  EXPECT_NE(message.find("link 'a': mesh geometry is not supported"), std::string::npos) << message;
}

TEST(RobotModel, ChainToALinkNotBelowTheBaseNamesFileAndLinks) {
  const TempDir dir;
  const std::string path =
      dir.write("robot.urdf", robot("<link name='a'/><link name='b'/><link name='c'/>" +
                                    revolute("j", "a", "b", kLimits) +
                                    "<joint name='f' type='fixed'><parent link='a'/>"
                                    "<child link='c'/></joint>"));
  const RobotModel model = load_robot_model(path);
  EXPECT_EQ(model.chain("a", "b"), std::vector<int>{model.joint_index("j")});
  EXPECT_EQ(config_error_of([&] { model.chain("b", "c"); }),
            path + ": no chain from 'b' to 'c' ('c' is not below 'b')");
  EXPECT_EQ(config_error_of([&] { model.chain("a", "tool"); }),
            path + ": no chain from 'a' to 'tool' (no link 'tool')");
}

TEST(RobotModel, ShippedTorsoHasTwoSevenJointArmsAndItsFrames) {
  const RobotModel model = load_robot_model(kShippedRobot);
  EXPECT_EQ(model.root, "base");
  int movable = 0;
  for (const RobotJoint& joint : model.joints) movable += joint.type != JointType::fixed;
  EXPECT_EQ(movable, 14);
  for (const std::string side : {"left", "right"}) {
    const std::vector<int> chain = model.chain("base", side + "_tool");
    std::vector<std::string> names;
    for (int j : chain)
      if (model.joints[j].type == JointType::revolute) names.push_back(model.joints[j].name);
    ASSERT_EQ(names.size(), 7u) << side;
    for (int i = 0; i < 7; ++i) EXPECT_EQ(names[i], side + "_joint_" + std::to_string(i + 1));
    for (const std::string link : {"_gripper", "_finger_1", "_finger_2", "_tool"})
      EXPECT_GE(model.link_index(side + link), 0) << side + link;
    EXPECT_EQ(model.links[model.link_index(side + "_tool")].mass, 0.0);
  }
  EXPECT_GE(model.link_index("head_camera"), 0);
  // Parents first, and every movable joint has a usable range.
  for (size_t j = 0; j < model.joints.size(); ++j) {
    const RobotJoint& joint = model.joints[j];
    bool parent_known = joint.parent == model.root;
    for (size_t k = 0; k < j; ++k)
      parent_known = parent_known || model.joints[k].child == joint.parent;
    EXPECT_TRUE(parent_known) << joint.name;
    if (joint.type != JointType::fixed) {
      EXPECT_LT(joint.lower, joint.upper) << joint.name;
      EXPECT_GT(joint.velocity, 0.0) << joint.name;
      EXPECT_GT(joint.effort, 0.0) << joint.name;
    }
  }
  const RobotLink& torso = model.links[model.link_index("torso")];
  EXPECT_GT(torso.mass, 0.0);
  ASSERT_EQ(torso.collisions.size(), 1u);
  EXPECT_EQ(torso.collisions[0].kind, RobotShape::Kind::box);
  ASSERT_EQ(torso.visuals.size(), 1u);
  EXPECT_NEAR(torso.visuals[0].colour.x(), 0.92f, 1e-6f);
}

}  // namespace
}  // namespace corrmp
