// bench_arm: speed of the simulated robot (the dual-arm torso in place of the
// paper's robot, Section IV-A and IV-C). The counter real_time_factor is
// simulated seconds per wall-clock second.
//   BM_ArmTick/7: one tick (1/240 s) of a seven-joint arm on a box base tracking
//     a joint trajectory: new joint targets, one Bullet step, the checks.
//   BM_ArmTick/14: the same for a torso with two seven-joint arms (a multibody per arm).
//   BM_WarmStartedIk: one inverse kinematics solve of the shipped torso's right
//     arm, warm-started at the last solution, the tool pointing down and moving
//     0.25 mm per solve around a 5 cm circle (the tasks' tool speeds per tick).
//   BM_CorridorTrialOnArms: the corridor expert's whole demonstration of one
//     scenario, executed by the right arm (configs/common/corridor_arms.yaml).
//   BM_CorridorTrialFloating: the same demonstration by the floating gripper,
//     the task's own cost without the arms.
//   BM_RopeTrialOnArms: a whole scripted half-hitch trial of the nominal
//     scenario on both arms (configs/common/rope_arms.yaml).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "bench_scripted_trial.hpp"
#include "core/config/config_loader.hpp"
#include "core/config/config_reader.hpp"
#include "envs/corridor_push/corridor_expert.hpp"
#include "envs/corridor_push/corridor_push.hpp"
#include "sim/robot/arm_kinematics.hpp"
#include "sim/robot/robot_dynamics.hpp"
#include "test_arms.hpp"

namespace corrmp {
namespace {

const std::string kSource = CORRMP_SOURCE_DIR;

// The `environment` section of a config file read into a task's parameters.
template <class Params>
Params environment_of(const std::string& config, Params params = {}) {
  ConfigNode root = load_config(kSource + "/" + config, {});
  ConfigReader::read(*root.find("environment"), "environment", params);
  return params;
}

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

void BM_WarmStartedIk(benchmark::State& state) {
  const DualArmParams arms;
  const RobotModel model = load_robot_model(kSource + "/" + arms.urdf);
  const ArmKinematics kinematics(model, arms.base_link, arms.right_tool, arms.ik);
  const Eigen::Vector3d centre(0.45, -0.2, 0.05);
  const double radius = 0.05, step = 0.00025;
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  target.linear() = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();  // tool down
  auto place = [&](long k) {
    const double angle = k * step / radius;
    target.translation() = centre + radius * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0);
  };
  place(0);
  Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(arms.right_home.data(), 7);
  q = kinematics.solve(target, q).q;
  long k = 0, failures = 0, iterations = 0;
  for (auto _ : state) {
    place(++k);
    const IkResult result = kinematics.solve(target, q);
    failures += result.status != IkResult::Status::ok;
    iterations += result.iterations;
    q = result.q;
  }
  state.counters["failures"] = failures;
  state.counters["iterations"] = benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_WarmStartedIk)->Unit(benchmark::kMicrosecond);

// The corridor expert's demonstration of one scenario, again and again; on the
// arms also the robot's simulated time (real_time_factor, simulated_s).
void time_corridor_demonstrations(benchmark::State& state, const CorridorPushParams& params) {
  CorridorPush env{params};
  const Scenario push{{"corridor_offset", 0.021}, {"object_dx", 0.0}, {"object_dy", 0.0}};
  CorridorExpert expert{CorridorExpertParams{}};
  double simulated = 0;
  int successes = 0;
  for (auto _ : state) {
    expert.demonstrate(env, push, false);
    successes += env.outcome().success;
    if (env.robot()) simulated += env.robot()->time();
  }
  if (env.robot()) {
    state.counters["real_time_factor"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
    state.counters["simulated_s"] = env.robot()->time();
  }
  state.counters["successes"] = benchmark::Counter(successes, benchmark::Counter::kAvgIterations);
}

void BM_CorridorTrialOnArms(benchmark::State& state) {
  time_corridor_demonstrations(
      state, environment_of<CorridorPushParams>("configs/common/corridor_arms.yaml"));
}
BENCHMARK(BM_CorridorTrialOnArms)->Unit(benchmark::kMillisecond);

void BM_CorridorTrialFloating(benchmark::State& state) {
  time_corridor_demonstrations(state, CorridorPushParams{});
}
BENCHMARK(BM_CorridorTrialFloating)->Unit(benchmark::kMillisecond);

void BM_RopeTrialOnArms(benchmark::State& state) {
  RopeKnotScene scene(environment_of<RopeKnotParams>("configs/common/rope_arms.yaml"));
  time_scripted_trials(state, scene);
}
BENCHMARK(BM_RopeTrialOnArms)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace corrmp

BENCHMARK_MAIN();
