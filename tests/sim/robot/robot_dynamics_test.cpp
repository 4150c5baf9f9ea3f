#include "sim/robot/robot_dynamics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "test_arms.hpp"

namespace corrmp {
namespace {

Eigen::Isometry3d base_pose() {
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  base.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  base.translation() = Eigen::Vector3d(0.3, -0.2, 0.8);
  return base;
}

// Deterministic configurations spread over the joint ranges.
Eigen::VectorXd spread(const RobotDynamics& robot, double phase) {
  const Eigen::VectorXd lo = robot.lower_limits(), hi = robot.upper_limits();
  Eigen::VectorXd q(robot.dof());
  for (int i = 0; i < robot.dof(); ++i)
    q[i] = lo[i] + (hi[i] - lo[i]) * (0.5 + 0.45 * std::sin(1.7 * i + phase));
  return q;
}

// Largest position (m) and rotation (rad) difference over all links.
std::pair<double, double> fk_error(const RobotModel& model, const RobotDynamics& robot,
                                   const Eigen::VectorXd& q) {
  const auto expected = test::forward_kinematics(model, base_pose(), q);
  double position = 0, rotation = 0;
  for (size_t i = 0; i < model.links.size(); ++i) {
    const Eigen::Isometry3d actual = robot.link_pose(model.links[i].name);
    position = std::max(position, (actual.translation() - expected[i].translation()).norm());
    rotation = std::max(
        rotation, Eigen::AngleAxisd(actual.linear().transpose() * expected[i].linear()).angle());
  }
  return {position, rotation};
}

// Bullet runs in single precision: poses agree with the double-precision
// model kinematics to float rounding of the joint positions and transforms.
constexpr double kFloatPoseTolerance = 1e-6;

TEST(RobotDynamics, LinkPosesAfterResetAreTheModelForwardKinematics) {
  for (const RobotModel& model :
       {test::three_joint_arm(), test::seven_joint_arm(), test::dual_arm()}) {
    RobotDynamics robot(model, RobotDynamicsParams{}, base_pose());
    for (double phase : {0.0, 1.0, 2.5, 4.0}) {
      const Eigen::VectorXd q = spread(robot, phase);
      robot.reset(q);
      const auto [position, rotation] = fk_error(model, robot, q);
      EXPECT_LT(position, kFloatPoseTolerance) << model.name << " phase " << phase;
      EXPECT_LT(rotation, kFloatPoseTolerance) << model.name << " phase " << phase;
    }
  }
}

TEST(RobotDynamics, HoldsAConfigurationAgainstGravity) {
  for (const RobotModel& model : {test::three_joint_arm(), test::seven_joint_arm()}) {
    RobotDynamics robot(model, RobotDynamicsParams{});
    const Eigen::VectorXd q = spread(robot, 1.0);
    robot.reset(q);
    double drift = 0;
    for (int tick = 0; tick < 480; ++tick) {
      robot.set_targets(q);
      robot.step();
      ASSERT_EQ(robot.check(), "") << robot.failure_detail();
      drift = std::max(drift, (robot.positions() - q).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(drift, 5e-4) << model.name;
  }
}

Eigen::VectorXd sinusoid(const RobotDynamics& robot, const Eigen::VectorXd& centre, double t) {
  Eigen::VectorXd q = centre;
  for (int i = 0; i < robot.dof(); ++i) q[i] += 0.5 * std::sin(2.0 * t + 0.7 * i);
  return q;
}

TEST(RobotDynamics, TracksASmoothJointTrajectory) {
  RobotDynamics robot(test::seven_joint_arm(), RobotDynamicsParams{});
  const Eigen::VectorXd centre = spread(robot, 2.5) * 0.5;
  robot.reset(sinusoid(robot, centre, 0.0));
  double squares = 0, worst = 0;
  const int ticks = 480;
  for (int tick = 1; tick <= ticks; ++tick) {
    const Eigen::VectorXd q = sinusoid(robot, centre, tick * robot.time_step());
    robot.set_targets(q);
    robot.step();
    ASSERT_EQ(robot.check(), "") << robot.failure_detail();
    const Eigen::VectorXd error = robot.positions() - q;
    squares += error.squaredNorm() / robot.dof();
    worst = std::max(worst, error.cwiseAbs().maxCoeff());
  }
  EXPECT_LT(std::sqrt(squares / ticks), 1e-4);
  EXPECT_LT(worst, 1e-3);
}

TEST(RobotDynamics, AJumpIsFollowedAtTheVelocityLimit) {
  const RobotModel model = test::seven_joint_arm();
  RobotDynamics robot(model, RobotDynamicsParams{});
  Eigen::VectorXd q = Eigen::VectorXd::Zero(robot.dof());
  q[0] = 1.5;
  q[3] = -1.0;
  robot.set_targets(q);
  double fastest = 0;
  bool reported = false;
  for (int tick = 0; tick < 300; ++tick) {
    robot.step();
    reported |= robot.check() == "tracking error";
    for (int i = 0; i < robot.dof(); ++i)
      fastest = std::max(fastest, std::abs(robot.velocities()[i]) / model.joints[i].velocity);
  }
  EXPECT_LT(fastest, 1.001);
  EXPECT_GT(fastest, 0.99);
  EXPECT_TRUE(reported);  // the jump is not a trajectory the arm can track
  EXPECT_EQ(robot.check(), "");
  EXPECT_LT((robot.positions() - q).cwiseAbs().maxCoeff(), 1e-3);
}

// The controller's torques come from its own inverse dynamics of the layout;
// Bullet's forward dynamics of the same bodies must then give every joint the
// velocity it was sent to, from any state, to Bullet's single precision (a
// missing velocity-dependent term is off by far more at these speeds).
TEST(RobotDynamics, EveryJointReachesItsCommandedVelocityInOneTick) {
  for (const RobotModel& model :
       {test::three_joint_arm(), test::seven_joint_arm(), test::dual_arm()}) {
    RobotDynamics robot(model, RobotDynamicsParams{}, base_pose());
    for (double phase : {0.0, 1.0, 2.5, 4.0}) {
      robot.reset(spread(robot, phase) * 0.8);
      // Up to 1.2 rad/s (0.18 m/s), reached over 0.25 s: the effort limits
      // never bind, and the velocity-dependent terms count.
      const int ticks = 60;
      double worst = 0;
      for (int tick = 1; tick <= ticks; ++tick) {
        Eigen::VectorXd velocity(robot.dof());
        for (int i = 0; i < robot.dof(); ++i)
          velocity[i] = std::min(0.6 * robot.velocity_limits()[i], 1.2) *
                        std::sin(2.3 * i + phase) * tick / ticks;
        robot.set_targets(robot.positions() + velocity * robot.time_step(), velocity);
        robot.step();
        ASSERT_EQ(robot.check(), "") << robot.failure_detail();
        worst = std::max(worst, (robot.velocities() - velocity).cwiseAbs().maxCoeff());
      }
      EXPECT_LT(worst, 1e-5) << model.name << " phase " << phase;
    }
  }
}

TEST(RobotDynamics, AJointWhoseEffortLimitBindsIsPushedAtTheLimit) {
  RobotModel model = test::seven_joint_arm();
  for (RobotJoint& joint : model.joints)
    if (joint.name == "joint2") joint.effort = 5.0;  // too weak to hold the arm out
  RobotDynamics robot(model, RobotDynamicsParams{});
  Eigen::VectorXd q = Eigen::VectorXd::Zero(robot.dof());
  q[1] = 1.2;
  robot.reset(q);
  const Eigen::VectorXd velocity = Eigen::VectorXd::Zero(robot.dof());
  robot.set_targets(q, velocity);
  robot.step();
  const Eigen::VectorXd after = robot.velocities();
  for (int i = 0; i < robot.dof(); ++i) {
    if (i == 1)
      EXPECT_GT(std::abs(after[i]), 1e-3) << "the weak joint sags";
    else
      EXPECT_LT(std::abs(after[i]), 1e-4) << "joint " << i << " still holds";
  }
}

TEST(RobotDynamics, FoldingTheArmOntoItselfIsASelfCollision) {
  RobotDynamics robot(test::seven_joint_arm(), RobotDynamicsParams{});
  Eigen::VectorXd folded = Eigen::VectorXd::Zero(robot.dof());
  folded[3] = 2.6;
  folded[5] = 2.6;
  robot.reset(folded);
  robot.set_targets(folded);
  robot.step();
  EXPECT_EQ(robot.check(), "self collision") << robot.failure_detail();
  // Links overlapping at q = 0 at their joints are not a collision.
  robot.reset(Eigen::VectorXd::Zero(robot.dof()));
  robot.step();
  EXPECT_EQ(robot.check(), "");
}

// The torso's arms are simulated apart (one multibody each): their links still
// collide with one another.
TEST(RobotDynamics, TheArmsOfOneTorsoTouchingIsASelfCollision) {
  RobotDynamics robot(test::dual_arm(), RobotDynamicsParams{});
  Eigen::VectorXd crossed = Eigen::VectorXd::Zero(robot.dof());
  crossed[1] = 1.64;
  crossed[3] = 0.51;
  crossed[8] = 1.82;
  crossed[10] = 0.77;
  robot.reset(crossed);
  robot.set_targets(crossed);
  robot.step();
  EXPECT_EQ(robot.check(), "self collision");
  EXPECT_EQ(robot.failure_detail(), "links 'left_link5' and 'right_link7' touch");
  robot.reset(Eigen::VectorXd::Zero(robot.dof()));
  robot.step();
  EXPECT_EQ(robot.check(), "") << robot.failure_detail();
}

TEST(RobotDynamics, AnArmHoldingStillIsBrakedUntilItsTargetsMove) {
  RobotDynamics robot(test::dual_arm(), RobotDynamicsParams{});
  const Eigen::VectorXd home = Eigen::VectorXd::Zero(robot.dof());
  robot.set_targets(home);
  robot.step();
  EXPECT_EQ(robot.braked_branches(), 2);
  const Eigen::VectorXd held = robot.positions();
  Eigen::VectorXd target = home;
  for (int tick = 1; tick <= 120; ++tick) {
    target[9] = 0.3 * tick / 120;  // the right arm's second joint
    robot.set_targets(target);
    robot.step();
    ASSERT_EQ(robot.check(), "") << robot.failure_detail();
    ASSERT_EQ(robot.braked_branches(), 1);
  }
  for (int tick = 0; tick < 240 && robot.braked_branches() < 2; ++tick) {
    robot.step();
    ASSERT_EQ(robot.check(), "") << robot.failure_detail();
  }
  EXPECT_EQ(robot.braked_branches(), 2);
  EXPECT_LE((robot.positions() - target).cwiseAbs().maxCoeff(),
            RobotDynamicsParams{}.brake_tolerance);
  EXPECT_EQ(robot.positions().head(7), held.head(7));  // the left arm never moved
  EXPECT_EQ(robot.velocities(), Eigen::VectorXd::Zero(robot.dof()));
  // A target velocity is a moving command, though the positions stay.
  Eigen::VectorXd velocities = Eigen::VectorXd::Zero(robot.dof());
  velocities[9] = 0.01;
  robot.set_targets(target, velocities);
  robot.step();
  EXPECT_EQ(robot.braked_branches(), 1);
  robot.reset(home);
  EXPECT_EQ(robot.braked_branches(), 0);

  RobotDynamicsParams never;
  never.brake_tolerance = 0;
  RobotDynamics unbraked(test::dual_arm(), never);
  unbraked.set_targets(home);
  for (int tick = 0; tick < 10; ++tick) unbraked.step();
  EXPECT_EQ(unbraked.braked_branches(), 0);
}

TEST(RobotDynamics, AnArmMovingIntoABrakedOneIsASelfCollision) {
  RobotDynamics robot(test::dual_arm(), RobotDynamicsParams{});
  Eigen::VectorXd crossed = Eigen::VectorXd::Zero(robot.dof());
  crossed[1] = 1.64;
  crossed[3] = 0.51;
  Eigen::VectorXd start = crossed;
  crossed[8] = 1.82;
  crossed[10] = 0.77;
  robot.reset(start);
  robot.step();
  ASSERT_EQ(robot.braked_branches(), 2);
  const Eigen::VectorXd braked = robot.positions();
  for (int tick = 1; tick <= 480 && robot.check().empty(); ++tick) {
    robot.set_targets(start + (crossed - start) * std::min(1.0, tick / 240.0));
    robot.step();
    if (robot.check().empty()) {
      ASSERT_EQ(robot.braked_branches(), 1);  // the left arm
    }
  }
  EXPECT_EQ(robot.check(), "self collision") << robot.failure_detail();
  EXPECT_NE(robot.failure_detail().find("'left_link"), std::string::npos) << robot.failure_detail();
  EXPECT_EQ(robot.positions().head(7), braked.head(7));  // it never moved, the colliding tick too
}

TEST(RobotDynamics, LinksOverlappingAtZeroOrListedAreNoSelfCollision) {
  RobotModel model = test::seven_joint_arm();
  // A housing around joint2 on link1 that reaches into link3 at q = 0.
  RobotShape housing;
  housing.kind = RobotShape::Kind::sphere;
  housing.size = Eigen::Vector3d(0.21, 0, 0);
  housing.origin.translation() = Eigen::Vector3d(0, 0, 0.15);
  model.links[1].collisions.push_back(housing);
  RobotDynamics robot(model, RobotDynamicsParams{});
  for (int tick = 0; tick < 10; ++tick) robot.step();
  EXPECT_EQ(robot.check(), "") << robot.failure_detail();

  // The wrist folded back: link7 onto link5, unless that pair is listed.
  Eigen::VectorXd wrist = Eigen::VectorXd::Zero(robot.dof());
  wrist[5] = 2.6;
  for (bool allowed : {false, true}) {
    RobotDynamics folded(
        test::seven_joint_arm(), RobotDynamicsParams{}, Eigen::Isometry3d::Identity(),
        allowed ? std::vector<std::pair<std::string, std::string>>{{"link7", "link5"}}
                : std::vector<std::pair<std::string, std::string>>{});
    folded.reset(wrist);
    folded.set_targets(wrist);
    folded.step();
    EXPECT_EQ(folded.check(), allowed ? "" : "self collision") << folded.failure_detail();
  }
}

TEST(RobotDynamics, TargetsBeyondTheLimitsAreClampedAndReported) {
  RobotDynamics robot(test::three_joint_arm(), RobotDynamicsParams{});
  Eigen::VectorXd q = Eigen::VectorXd::Zero(robot.dof());
  q[1] = robot.upper_limits()[1] + 0.5;
  robot.set_targets(q);
  for (int tick = 0; tick < 480; ++tick) {
    robot.step();
    ASSERT_EQ(robot.check(), "joint limit");
  }
  EXPECT_NEAR(robot.positions()[1], robot.upper_limits()[1], 1e-3);
  EXPECT_EQ(robot.failure_detail(), "joint 'joint2' commanded to 2.5 beyond [-2, 2]");
}

TEST(RobotDynamics, ABlowUpIsAPhysicsFault) {
  RobotDynamicsParams params;
  params.gravity = 1e38;
  RobotDynamics robot(test::three_joint_arm(), params);
  robot.reset(Eigen::Vector3d(0.0, 1.0, 0.0));
  for (int tick = 0; tick < 5 && robot.check() != "physics fault"; ++tick) robot.step();
  EXPECT_EQ(robot.check(), "physics fault");
}

Eigen::MatrixXd run_trajectory() {
  RobotDynamics robot(test::seven_joint_arm(), RobotDynamicsParams{});
  const Eigen::VectorXd centre = spread(robot, 1.0) * 0.5;
  robot.reset(sinusoid(robot, centre, 0.0));
  Eigen::MatrixXd positions(robot.dof(), 240);
  for (int tick = 0; tick < 240; ++tick) {
    robot.set_targets(sinusoid(robot, centre, (tick + 1) * robot.time_step()));
    robot.step();
    positions.col(tick) = robot.positions();
  }
  return positions;
}

TEST(RobotDynamics, AFreshRobotReplaysBitIdentically) {
  const Eigen::MatrixXd first = run_trajectory();
  const Eigen::MatrixXd second = run_trajectory();
  EXPECT_TRUE((first.array() == second.array()).all());
}

}  // namespace
}  // namespace corrmp
