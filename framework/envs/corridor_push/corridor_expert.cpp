// The emulated human demonstrator of the corridor task.
#include "envs/corridor_push/corridor_expert.hpp"

#include <fmt/format.h>

#include "core/thread_budget.hpp"
#include "data/expert_collection.hpp"
#include "envs/corridor_push/path_sampling.hpp"

namespace corrmp {

namespace {

CorridorPush& as_corridor(Environment& environment) {
  auto* corridor = dynamic_cast<CorridorPush*>(&environment);
  if (corridor == nullptr) {
    throw std::runtime_error("corridor_expert demonstrates only the corridor_push environment");
  }
  return *corridor;
}

SegmentTrajectory segment_of(const std::string& name, const Eigen::MatrixXd& path,
                             Observation start) {
  return SegmentTrajectory{name, normalised_time(static_cast<int>(path.rows())), path,
                           Eigen::VectorXd(), std::move(start)};
}

}  // namespace

std::string CorridorExpert::decide(const CorridorPush& env) {
  const double misalignment = env.corridor_x() - env.object_position().x();
  if (misalignment > env.params().tolerance) return "push";
  if (misalignment < -env.params().tolerance) return "pull";
  return "none";
}

std::vector<Eigen::Vector3d> CorridorExpert::pre_waypoints(const CorridorPush& env) {
  const auto& p = env.params();
  const Eigen::Vector3d start = env.effector_position().transpose();
  const Eigen::Vector3d object = env.object_position();
  const double contact_y = object.y() - env.object_half_size() - env.tool_half_width_y();
  return {start,
          {object.x(), start.y(), p.push_height},
          {object.x(), contact_y + p.pre_push_distance, p.push_height}};
}

std::vector<Eigen::Vector3d> CorridorExpert::cor_waypoints(const CorridorPush& env,
                                                           const std::string& decision) {
  const auto& p = env.params();
  const Eigen::Vector3d start = env.effector_position().transpose();
  const Eigen::Vector3d o = env.object_position();
  const double zp = p.push_height, zl = p.lift_height;
  const double back_y = o.y() - env.object_half_size() - env.tool_half_width_y() - p.standoff;
  // The expert goes round the object at table height to its -x side (push) or
  // +x side (pull), pushes it by the shift (0 when no correction is needed,
  // from the side the misalignment points to), lifts and comes back behind it.
  // Every decision has the same shape, so a CNMP blending two neighbouring
  // demonstrations still produces a harmless motion.
  const double shift = decision == "none" ? 0.0 : env.corridor_x() - o.x();
  const double side = env.corridor_x() - o.x() >= 0.0 ? -1.0 : 1.0;
  const double contact = env.object_half_size() + env.tool_half_width_x();
  const double approach_x = o.x() + side * (contact + p.standoff);
  const double pushed_x = o.x() + side * contact + shift;
  return {start,
          {start.x(), back_y, zp},
          {approach_x, back_y, zp},
          {approach_x, o.y(), zp},
          {pushed_x, o.y(), zp},
          {pushed_x, o.y(), zl},
          {o.x() + shift, back_y, zl},
          {o.x() + shift, back_y, zp}};
}

std::vector<double> CorridorExpert::cor_slowness() {
  constexpr double kPushing = 3.0;  // the pushing edge: approach -> pushed
  return {1.0, 1.0, 1.0, kPushing, 1.0, 1.0, 1.0};
}

std::vector<Eigen::Vector3d> CorridorExpert::post_waypoints(const CorridorPush& env) {
  const auto& p = env.params();
  const Eigen::Vector3d start = env.effector_position().transpose();
  const Eigen::Vector3d o = env.object_position();
  const double target_y = env.corridor_mid_y() + p.pass_margin;
  const double contact_y = target_y - env.object_half_size() - env.tool_half_width_y();
  return {start,
          {o.x(), start.y(), p.push_height},
          {o.x(), contact_y, p.push_height},
          {o.x(), contact_y - p.standoff, p.push_height},
          {o.x(), contact_y - p.standoff, p.lift_height}};
}

Demonstration CorridorExpert::demonstrate(Environment& environment, const Scenario& scenario,
                                          bool with_images) {
  return demonstrate(environment, scenario, with_images, nullptr);
}

Demonstration CorridorExpert::demonstrate(Environment& environment, const Scenario& scenario,
                                          bool with_images, Rng* tempo_rng) const {
  CorridorPush& env = as_corridor(environment);
  const auto& p = env.params();
  env.reset(scenario);
  Demonstration demo;
  demo.scenario = scenario_json(scenario);
  // The whole skill as one timed path: every stroke's waypoints and slowness.
  std::vector<Eigen::Vector3d> skill_waypoints;
  std::vector<double> skill_slowness;
  std::vector<double> segment_durations;
  auto run = [&](const std::string& name, const std::vector<Eigen::Vector3d>& waypoints, int points,
                 Observation start, std::vector<double> slowness) {
    if (slowness.empty()) slowness.assign(waypoints.size() - 1, 1.0);
    for (double& s : slowness) s *= tempo_rng ? tempo_factor(*tempo_rng) : 1.0;
    const Eigen::MatrixXd path = sample_path(waypoints, points, slowness);
    const std::string failure = env.execute(name, path);
    if (!failure.empty())
      throw std::runtime_error("the expert's " + name + "-MP failed: " + failure);
    demo.segments.push_back(segment_of(name, path, std::move(start)));
    skill_waypoints.insert(skill_waypoints.end(),
                           waypoints.begin() + (skill_waypoints.empty() ? 0 : 1), waypoints.end());
    skill_slowness.insert(skill_slowness.end(), slowness.begin(), slowness.end());
    segment_durations.push_back(weighted_length(waypoints, slowness));
  };
  Observation initial = env.observe(false);
  run("pre", pre_waypoints(env), p.pre_points, initial, {});
  Observation critical = env.observe(with_images);
  demo.decision = decide(env);
  run("cor", cor_waypoints(env, demo.decision), p.cor_points, critical, cor_slowness());
  run("post", post_waypoints(env), p.post_points, env.observe(with_images), {});

  // The whole skill as the demonstrator's recording at a fixed rate: time is
  // uniform in the timed path, so the critical points fall wherever this
  // demonstration's tempo put them. Each segment's span is kept.
  const int total = p.pre_points + p.cor_points + p.post_points;
  const Eigen::MatrixXd full = sample_path(skill_waypoints, total, skill_slowness);
  double elapsed = 0.0, duration = 0.0;
  for (double d : segment_durations) duration += d;
  for (size_t i = 0; i < segment_durations.size(); ++i) {
    demo.segments[i].phase_begin = duration > 0 ? elapsed / duration : 0.0;
    elapsed += segment_durations[i];
    demo.segments[i].phase_end = duration > 0 ? elapsed / duration : 1.0;
  }
  demo.segments.push_back(segment_of("full", full, initial));
  demo.segments.back().phase_begin = 0.0;
  demo.segments.back().phase_end = 1.0;
  return demo;
}

// Drawn whatever the variation (exactly 1 at 0), so the scenarios collected
// never depend on it and a sweep over it compares the same scenarios.
double CorridorExpert::tempo_factor(Rng& rng) const {
  const double v = params_.tempo_variation;
  return rng.uniform(1.0 - v, 1.0 + v);
}

DemonstrationSplit CorridorExpert::collect(Environment* environment, Rng& rng) {
  if (environment == nullptr) throw std::runtime_error("corridor_expert needs an environment");
  const ExpertCollection wanted{params_.train, params_.validation,
                                (params_.train + params_.validation) * params_.max_attempts_factor,
                                "corridor_expert"};
  EnvironmentCopies environments(*environment, parallel_workers(wanted.max_attempts));
  return collect_expert_demonstrations(
      wanted, rng, environments.size(), [&](Rng& attempt_rng, int worker) {
        Environment& env = environments[worker];
        const Scenario scenario = env.sample_scenario(attempt_rng);
        Demonstration demo = demonstrate(env, scenario, params_.images, &attempt_rng);
        const Outcome outcome = env.outcome();
        if (!outcome.success) {
          throw std::runtime_error(scenario_json(scenario) + ": " + outcome.failure);
        }
        return demo;
      });
}

}  // namespace corrmp
