// The joint controller's arithmetic, without Bullet: rigid-body inverse
// dynamics of a fixed-base chain (recursive Newton-Euler in the world frame)
// and the joint forces that give each joint a commanded velocity after one
// tick, within its effort limit.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace corrmp {

// One body of a fixed-base kinematic tree at its current state; parents come
// before their children. All vectors in the world frame.
struct ChainBody {
  int parent = -1;  // index of the parent body; -1: the fixed base
  bool revolute = true;
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the centre of mass
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit joint axis
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();  // a point on the joint axis
};

// The joint forces (N m, or N for a prismatic joint) that give the joints the
// accelerations `qdd` at velocities `qd` under `gravity` (m/s^2):
// M(q) qdd + h(q, qd).
Eigen::VectorXd inverse_dynamics(const std::vector<ChainBody>& bodies, const Eigen::VectorXd& qd,
                                 const Eigen::VectorXd& qdd, const Eigen::Vector3d& gravity);

// The joint-space inertia M(q).
Eigen::MatrixXd joint_inertia(const std::vector<ChainBody>& bodies);

// The joint forces that bring the joints from velocities `qd` to `target`
// after a tick of `dt` (semi-implicit Euler: qd + dt qdd), each within
// [-effort, effort]: the joints whose effort limit does not bind reach their
// target exactly; a joint whose limit binds is pushed at the limit towards its
// target. `bias` is h(q, qd) (inverse_dynamics with zero accelerations) and
// `inertia` is M(q).
Eigen::VectorXd bounded_joint_forces(const Eigen::MatrixXd& inertia, const Eigen::VectorXd& bias,
                                     const Eigen::VectorXd& qd, const Eigen::VectorXd& target,
                                     const Eigen::VectorXd& effort, double dt);

// The same forces by projected Gauss-Seidel sweeps from `start`: slower, but
// always converging; bounded_joint_forces falls back on it where its active
// set does not settle.
Eigen::VectorXd bounded_joint_forces_by_sweeps(
    const Eigen::MatrixXd& inertia, const Eigen::VectorXd& bias, const Eigen::VectorXd& qd,
    const Eigen::VectorXd& target, const Eigen::VectorXd& effort, double dt, Eigen::VectorXd start);

}  // namespace corrmp
