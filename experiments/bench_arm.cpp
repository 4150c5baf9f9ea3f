// bench_arm: speed of the Bullet multibody robot tracking a joint trajectory
// (the simulated arm in place of the paper's robot, Section IV-A). One
// iteration is one tick (1/240 s): new joint targets, one Bullet step, the
// checks. The counter real_time_factor is simulated seconds per wall-clock second.
//   BM_ArmTick/7: a seven-joint arm on a box base.
//   BM_ArmTick/14: a torso with two seven-joint arms, one multibody.
#include <benchmark/benchmark.h>

#include <cmath>

#include "sim/robot/robot_dynamics.hpp"
#include "test_arms.hpp"

namespace corrmp {
namespace {

void BM_ArmTick(benchmark::State& state) {
  const RobotModel model = state.range(0) == 7 ? test::seven_joint_arm() : test::dual_arm();
  RobotDynamics robot(model, RobotDynamicsParams{});
  const Eigen::VectorXd centre = 0.3 * (robot.lower_limits() + robot.upper_limits()) / 2 +
                                 0.2 * Eigen::VectorXd::Ones(robot.dof());
  auto target = [&](double t) {
    Eigen::VectorXd q = centre;
    for (int i = 0; i < robot.dof(); ++i) q[i] += 0.5 * std::sin(2.0 * t + 0.7 * i);
    return q;
  };
  robot.reset(target(0.0));
  int failures = 0;
  for (auto _ : state) {
    robot.set_targets(target(robot.time() + robot.time_step()));
    robot.step();
    failures += !robot.check().empty();
  }
  state.counters["real_time_factor"] =
      benchmark::Counter(robot.time(), benchmark::Counter::kIsRate);
  state.counters["joints"] = robot.dof();
  state.counters["failed_ticks"] = failures;
}
BENCHMARK(BM_ArmTick)->Arg(7)->Arg(14)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace corrmp

BENCHMARK_MAIN();
