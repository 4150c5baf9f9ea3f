#include "sim/robot/joint_torques.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace corrmp {
namespace {

// A tree of `count` bodies (each hung from a random earlier one), revolute
// and prismatic joints with tilted axes, at a pseudo-random state from `seed`.
std::vector<ChainBody> chain(unsigned seed, int count = 6) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto vec = [&] { return Eigen::Vector3d(u(rng), u(rng), u(rng)); };
  std::vector<ChainBody> bodies(count);
  for (int b = 0; b < count; ++b) {
    ChainBody& body = bodies[b];
    body.parent = b == 0 ? -1 : static_cast<int>(std::uniform_int_distribution<>(0, b - 1)(rng));
    body.revolute = u(rng) > -0.6;
    body.mass = 1.0 + 0.5 * (u(rng) + 1.0);
    const Eigen::Matrix3d r =
        Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng) + 2.0).normalized().toRotationMatrix();
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

// A planar two-link arm (both axes along y, gravity along -z) against its
// textbook equations: M(q) qdd + C(q, qd) qd + g(q), Coriolis and centrifugal
// terms included.
TEST(JointTorques, ATwoLinkArmFollowsItsClosedForm) {
  const double m1 = 2.0, m2 = 1.5, l1 = 0.4, c1 = 0.18, c2 = 0.22, i1 = 0.03, i2 = 0.02, g = 9.81;
  for (const double q1 : {-0.7, 0.3, 1.9}) {
    for (const double q2 : {-1.2, 0.5, 2.4}) {
      // Rotating by t about +y takes x to (cos t, 0, -sin t).
      auto along = [](double t) { return Eigen::Vector3d(std::cos(t), 0, -std::sin(t)); };
      std::vector<ChainBody> bodies(2);
      for (ChainBody& body : bodies) body.axis = Eigen::Vector3d::UnitY();
      bodies[0].mass = m1;
      bodies[0].inertia = Eigen::Vector3d(0.01, i1, 0.05).asDiagonal();
      bodies[0].com = c1 * along(q1);
      bodies[1].parent = 0;
      bodies[1].mass = m2;
      bodies[1].inertia = Eigen::Vector3d(0.04, i2, 0.01).asDiagonal();
      bodies[1].pivot = l1 * along(q1);
      bodies[1].com = bodies[1].pivot + c2 * along(q1 + q2);
      const Eigen::Vector2d qd(0.8, -1.3), qdd(2.1, 0.6);
      Eigen::Matrix2d inertia;
      inertia(0, 0) =
          i1 + i2 + m1 * c1 * c1 + m2 * (l1 * l1 + c2 * c2 + 2 * l1 * c2 * std::cos(q2));
      inertia(0, 1) = inertia(1, 0) = i2 + m2 * (c2 * c2 + l1 * c2 * std::cos(q2));
      inertia(1, 1) = i2 + m2 * c2 * c2;
      const double k = m2 * l1 * c2 * std::sin(q2);
      const Eigen::Vector2d coriolis(-k * (2 * qd[0] * qd[1] + qd[1] * qd[1]), k * qd[0] * qd[0]);
      const Eigen::Vector2d gravity(
          -g * ((m1 * c1 + m2 * l1) * std::cos(q1) + m2 * c2 * std::cos(q1 + q2)),
          -g * m2 * c2 * std::cos(q1 + q2));
      const Eigen::VectorXd expected = inertia * qdd + coriolis + gravity;
      const Eigen::VectorXd tau = inverse_dynamics(bodies, qd, qdd, Eigen::Vector3d(0, 0, -g));
      EXPECT_LT((tau - expected).cwiseAbs().maxCoeff(), 1e-12) << q1 << " " << q2;
    }
  }
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
  for (unsigned seed = 0; seed < 300; ++seed) {
    const int n = 3 + static_cast<int>(seed % 5);
    const std::vector<ChainBody> bodies = chain(seed, n);
    const Eigen::MatrixXd inertia = joint_inertia(bodies);
    const Eigen::VectorXd qd = Eigen::VectorXd::LinSpaced(n, -0.5, 0.5);
    const Eigen::VectorXd bias =
        inverse_dynamics(bodies, qd, Eigen::VectorXd::Zero(n), Eigen::Vector3d(0, 0, -9.81));
    const double dt = 1.0 / 240.0;
    Eigen::VectorXd target(n);
    for (int i = 0; i < n; ++i) target[i] = std::sin(seed + 1.7 * i);
    // Strong joints: the unbounded solution.
    const Eigen::VectorXd strong = Eigen::VectorXd::Constant(n, 1e6);
    const Eigen::VectorXd free_tau = bounded_joint_forces(inertia, bias, qd, target, strong, dt);
    EXPECT_LT((free_tau - (inertia * (target - qd) / dt + bias)).cwiseAbs().maxCoeff(), 1e-9);
    // Weak joints: some limits bind, down to nearly all of them.
    Eigen::VectorXd weak = free_tau.cwiseAbs() * (0.05 + 0.15 * (seed % 6));
    weak = weak.cwiseMax(0.05);
    const Eigen::VectorXd tau = bounded_joint_forces(inertia, bias, qd, target, weak, dt);
    expect_bounded(inertia, bias, qd, target, weak, dt, tau);
    // The fallback reaches the same forces from the unbounded ones.
    const Eigen::VectorXd swept =
        bounded_joint_forces_by_sweeps(inertia, bias, qd, target, weak, dt, free_tau);
    expect_bounded(inertia, bias, qd, target, weak, dt, swept);
    EXPECT_LT((swept - tau).cwiseAbs().maxCoeff(), 1e-6 * weak.maxCoeff()) << seed;
  }
}

}  // namespace
}  // namespace corrmp
