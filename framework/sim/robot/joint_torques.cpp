// Recursive Newton-Euler inverse dynamics and the effort-bounded joint forces.
#include "sim/robot/joint_torques.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace corrmp {

Eigen::VectorXd inverse_dynamics(const std::vector<ChainBody>& bodies, const Eigen::VectorXd& qd,
                                 const Eigen::VectorXd& qdd, const Eigen::Vector3d& gravity) {
  const int n = static_cast<int>(bodies.size());
  // Forward: each body's angular velocity and acceleration and its centre of
  // mass's acceleration; the base's acceleration stands in for gravity.
  std::vector<Eigen::Vector3d> omega(n), alpha(n), accel(n);
  for (int b = 0; b < n; ++b) {
    const ChainBody& body = bodies[b];
    const int p = body.parent;
    const Eigen::Vector3d parent_omega = p < 0 ? Eigen::Vector3d::Zero() : omega[p];
    const Eigen::Vector3d parent_alpha = p < 0 ? Eigen::Vector3d::Zero() : alpha[p];
    Eigen::Vector3d pivot_accel = -gravity;  // the parent's point at the pivot
    if (p >= 0) {
      const Eigen::Vector3d r = body.pivot - bodies[p].com;
      pivot_accel = accel[p] + parent_alpha.cross(r) + parent_omega.cross(parent_omega.cross(r));
    }
    const Eigen::Vector3d d = body.com - body.pivot;
    if (body.revolute) {
      omega[b] = parent_omega + body.axis * qd[b];
      alpha[b] = parent_alpha + body.axis * qdd[b] + parent_omega.cross(body.axis * qd[b]);
    } else {
      omega[b] = parent_omega;
      alpha[b] = parent_alpha;
      pivot_accel += 2.0 * parent_omega.cross(body.axis * qd[b]) + body.axis * qdd[b];
    }
    accel[b] = pivot_accel + alpha[b].cross(d) + omega[b].cross(omega[b].cross(d));
  }
  // Backward: the force and the moment about its pivot that each body's
  // joint transmits, carrying its children's.
  std::vector<Eigen::Vector3d> force(n, Eigen::Vector3d::Zero()),
      moment(n, Eigen::Vector3d::Zero());
  Eigen::VectorXd tau(n);
  for (int b = n - 1; b >= 0; --b) {
    const ChainBody& body = bodies[b];
    const Eigen::Vector3d f = body.mass * accel[b];
    force[b] += f;
    moment[b] += body.inertia * alpha[b] + omega[b].cross(body.inertia * omega[b]) +
                 (body.com - body.pivot).cross(f);
    tau[b] = body.axis.dot(body.revolute ? moment[b] : force[b]);
    if (body.parent >= 0) {
      force[body.parent] += force[b];
      moment[body.parent] += moment[b] + (body.pivot - bodies[body.parent].pivot).cross(force[b]);
    }
  }
  return tau;
}

Eigen::MatrixXd joint_inertia(const std::vector<ChainBody>& bodies) {
  const int n = static_cast<int>(bodies.size());
  Eigen::MatrixXd inertia(n, n);
  const Eigen::VectorXd still = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < n; ++j)
    inertia.col(j) =
        inverse_dynamics(bodies, still, Eigen::VectorXd::Unit(n, j), Eigen::Vector3d::Zero());
  return inertia;
}

namespace {

// The bounded forces' optimality conditions hold for `tau` (within a relative
// tolerance): every force within its limit, a joint below its limit reaching
// its target, a joint at its limit falling short of it, not overshooting.
bool satisfies_bounds(const Eigen::MatrixXd& inertia, const Eigen::VectorXd& bias,
                      const Eigen::VectorXd& wanted, const Eigen::VectorXd& effort,
                      const Eigen::VectorXd& tau) {
  const Eigen::VectorXd accel = inertia.ldlt().solve(tau - bias);
  const double tolerance = 1e-9 * (1.0 + wanted.cwiseAbs().maxCoeff());
  for (int i = 0; i < tau.size(); ++i) {
    if (!(std::abs(tau[i]) <= effort[i])) return false;
    const double short_of = (tau[i] > 0 ? 1.0 : -1.0) * (accel[i] - wanted[i]);
    if (std::abs(tau[i]) < effort[i] ? std::abs(accel[i] - wanted[i]) > tolerance
                                     : short_of > tolerance)
      return false;
  }
  return true;
}

}  // namespace

// The forces solve a convex problem: minimise 1/2 (tau - tau*)' M^-1 (tau - tau*)
// over the box |tau| <= effort, tau* the unbounded forces (its gradient is the
// acceleration's excess over the wanted one). An active set usually solves it
// in a round or two; where that does not settle, projected Gauss-Seidel on the
// same problem converges (its Hessian is positive definite).
Eigen::VectorXd bounded_joint_forces(const Eigen::MatrixXd& inertia, const Eigen::VectorXd& bias,
                                     const Eigen::VectorXd& qd, const Eigen::VectorXd& target,
                                     const Eigen::VectorXd& effort, double dt) {
  const int n = static_cast<int>(qd.size());
  const Eigen::VectorXd wanted = (target - qd) / dt;  // accelerations
  const Eigen::VectorXd unbounded = inertia * wanted + bias;
  Eigen::VectorXd tau = unbounded;
  // Active set: `bound[i]` is +1 or -1 while joint i is held at that effort
  // limit (its acceleration then follows), 0 while it reaches its target.
  std::vector<int> bound(n, 0);
  for (int round = 0; round < 4 * n + 1; ++round) {
    std::vector<int> held, free;
    for (int i = 0; i < n; ++i) (bound[i] ? held : free).push_back(i);
    Eigen::VectorXd accel = wanted;
    if (!held.empty()) {
      const int h = static_cast<int>(held.size());
      Eigen::MatrixXd inertia_held(h, h);
      Eigen::VectorXd rhs(h);
      for (int a = 0; a < h; ++a) {
        rhs[a] = bound[held[a]] * effort[held[a]] - bias[held[a]];
        for (int i : free) rhs[a] -= inertia(held[a], i) * wanted[i];
        for (int b = 0; b < h; ++b) inertia_held(a, b) = inertia(held[a], held[b]);
      }
      const Eigen::VectorXd accel_held = inertia_held.ldlt().solve(rhs);
      for (int a = 0; a < h; ++a) accel[held[a]] = accel_held[a];
    }
    tau = inertia * accel + bias;
    for (int i : held) tau[i] = bound[i] * effort[i];
    // The free joint furthest past its limit is held next; a held joint
    // that would overshoot its target is freed.
    int worst = -1;
    double excess = 0.0;
    for (int i : free) {
      if (std::abs(tau[i]) - effort[i] > excess) excess = std::abs(tau[i]) - effort[i], worst = i;
    }
    if (worst >= 0) {
      bound[worst] = tau[worst] > 0 ? 1 : -1;
      continue;
    }
    bool freed = false;
    for (int i : held) {
      if (bound[i] * (accel[i] - wanted[i]) > 0) bound[i] = 0, freed = true;
    }
    if (!freed) break;
  }
  tau = tau.cwiseMax(-effort).cwiseMin(effort);
  if (satisfies_bounds(inertia, bias, wanted, effort, tau)) return tau;
  return bounded_joint_forces_by_sweeps(inertia, bias, qd, target, effort, dt, tau);
}

Eigen::VectorXd bounded_joint_forces_by_sweeps(
    const Eigen::MatrixXd& inertia, const Eigen::VectorXd& bias, const Eigen::VectorXd& qd,
    const Eigen::VectorXd& target, const Eigen::VectorXd& effort, double dt, Eigen::VectorXd tau) {
  const int n = static_cast<int>(qd.size());
  const Eigen::VectorXd unbounded = inertia * ((target - qd) / dt) + bias;
  tau = tau.cwiseMax(-effort).cwiseMin(effort);
  const Eigen::MatrixXd hessian = inertia.inverse();
  for (int sweep = 0; sweep < 100000; ++sweep) {
    double change = 0.0;
    for (int i = 0; i < n; ++i) {
      const double gradient = hessian.row(i).dot(tau - unbounded);
      const double next = std::clamp(tau[i] - gradient / hessian(i, i), -effort[i], effort[i]);
      change = std::max(change, std::abs(next - tau[i]));
      tau[i] = next;
    }
    if (change <= 1e-12 * (1.0 + effort.maxCoeff())) break;
  }
  return tau;
}

}  // namespace corrmp
