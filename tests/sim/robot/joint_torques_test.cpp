#include "sim/robot/joint_torques.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace corrmp {
namespace {

// A branching chain of revolute and prismatic joints with tilted axes, at a
// pseudo-random state from `seed`.
std::vector<ChainBody> chain(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto vec = [&] { return Eigen::Vector3d(u(rng), u(rng), u(rng)); };
  std::vector<ChainBody> bodies(6);
  const int parents[6] = {-1, 0, 1, 2, 1, 4};
  for (int b = 0; b < 6; ++b) {
    ChainBody& body = bodies[b];
    body.parent = parents[b];
    body.revolute = b != 3;
    body.mass = 1.0 + 0.5 * (u(rng) + 1.0);
    const Eigen::Matrix3d r = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    body.inertia = r * Eigen::Vector3d(0.02, 0.03, 0.04).asDiagonal() * r.transpose();
    body.pivot =
        (body.parent < 0 ? Eigen::Vector3d::Zero() : bodies[body.parent].com) + 0.2 * vec();
    body.com = body.pivot + 0.15 * vec();
    body.axis = vec().normalized();
  }
  return bodies;
}

TEST(JointTorques, InverseDynamicsIsTheInertiaTimesAccelerationPlusTheBias) {
  for (unsigned seed = 0; seed < 5; ++seed) {
    const std::vector<ChainBody> bodies = chain(seed);
    const Eigen::VectorXd qd = Eigen::VectorXd::LinSpaced(6, -1.0, 1.5);
    const Eigen::VectorXd qdd = Eigen::VectorXd::LinSpaced(6, 2.0, -3.0);
    const Eigen::Vector3d gravity(0, 0, -9.81);
    const Eigen::MatrixXd inertia = joint_inertia(bodies);
    EXPECT_LT((inertia - inertia.transpose()).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_EQ(inertia.ldlt().info(), Eigen::Success);
    EXPECT_TRUE(inertia.ldlt().isPositive());
    const Eigen::VectorXd bias = inverse_dynamics(bodies, qd, Eigen::VectorXd::Zero(6), gravity);
    const Eigen::VectorXd tau = inverse_dynamics(bodies, qd, qdd, gravity);
    EXPECT_LT((tau - (inertia * qdd + bias)).cwiseAbs().maxCoeff(), 1e-10);
  }
}

// The power the joint forces put in is the rate of change of kinetic plus
// potential energy: tau . qd = d/dt (T + V), checked on the chain moving along
// qd for a small time (the bodies moved by the joints' motion).
TEST(JointTorques, JointPowerIsTheEnergysRateOfChange) {
  // A single revolute body about a fixed axis: T = 1/2 I_axis qd^2, so
  // tau = I_axis qdd + gravity's moment; checked directly.
  ChainBody body;
  body.mass = 2.0;
  body.inertia = Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal();
  body.pivot = Eigen::Vector3d::Zero();
  body.com = Eigen::Vector3d(0.5, 0, 0);
  body.axis = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d gravity(0, 0, -9.81);
  const double i_axis = 0.2 + 2.0 * 0.25;  // parallel axes
  const Eigen::VectorXd qd = Eigen::VectorXd::Constant(1, 0.7);
  const Eigen::VectorXd qdd = Eigen::VectorXd::Constant(1, 1.3);
  const double tau = inverse_dynamics({body}, qd, qdd, gravity)[0];
  // Gravity's moment about +y of a mass at +x pulling down is +m g x about y.
  EXPECT_NEAR(tau, i_axis * 1.3 - 2.0 * 9.81 * 0.5, 1e-12);
}

// Complementarity: a free joint reaches its target, a held joint is at its
// effort limit and short of its target, every force within its limit.
void expect_bounded(const Eigen::MatrixXd& inertia, const Eigen::VectorXd& bias,
                    const Eigen::VectorXd& qd, const Eigen::VectorXd& target,
                    const Eigen::VectorXd& effort, double dt, const Eigen::VectorXd& tau) {
  const Eigen::VectorXd reached = qd + dt * inertia.ldlt().solve(tau - bias);
  for (int i = 0; i < tau.size(); ++i) {
    ASSERT_LE(std::abs(tau[i]), effort[i] * (1 + 1e-12)) << i;
    if (std::abs(tau[i]) < effort[i] * (1 - 1e-9)) {
      EXPECT_NEAR(reached[i], target[i], 1e-9) << i;
    } else {
      EXPECT_LE((tau[i] > 0 ? 1 : -1) * (reached[i] - target[i]), 1e-9) << i;
    }
  }
}

TEST(JointTorques, BoundedForcesReachTheTargetsOfJointsWithinTheirLimits) {
  for (unsigned seed = 0; seed < 20; ++seed) {
    const std::vector<ChainBody> bodies = chain(seed);
    const Eigen::MatrixXd inertia = joint_inertia(bodies);
    const Eigen::VectorXd qd = Eigen::VectorXd::LinSpaced(6, -0.5, 0.5);
    const Eigen::VectorXd bias =
        inverse_dynamics(bodies, qd, Eigen::VectorXd::Zero(6), Eigen::Vector3d(0, 0, -9.81));
    const double dt = 1.0 / 240.0;
    Eigen::VectorXd target(6);
    for (int i = 0; i < 6; ++i) target[i] = std::sin(seed + 1.7 * i);
    // Strong joints: the unbounded solution.
    const Eigen::VectorXd strong = Eigen::VectorXd::Constant(6, 1e6);
    const Eigen::VectorXd free_tau = bounded_joint_forces(inertia, bias, qd, target, strong, dt);
    EXPECT_LT((free_tau - (inertia * (target - qd) / dt + bias)).cwiseAbs().maxCoeff(), 1e-9);
    // Weak joints: some limits bind.
    Eigen::VectorXd weak = free_tau.cwiseAbs() * (0.3 + 0.1 * (seed % 5));
    weak = weak.cwiseMax(0.5);
    const Eigen::VectorXd tau = bounded_joint_forces(inertia, bias, qd, target, weak, dt);
    expect_bounded(inertia, bias, qd, target, weak, dt, tau);
  }
}

}  // namespace
}  // namespace corrmp
