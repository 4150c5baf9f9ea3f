// The teacher of the via-point reach (via_point_expert.hpp).
#include "envs/via_point/via_point_expert.hpp"

#include <stdexcept>

#include "core/thread_budget.hpp"
#include "data/expert_collection.hpp"
#include "envs/via_point/via_point_paths.hpp"

namespace corrmp {

namespace {

ViaPoint& as_via_point(Environment& environment) {
  auto* task = dynamic_cast<ViaPoint*>(&environment);
  if (task == nullptr) {
    throw std::runtime_error("via_point_expert demonstrates only the via_point environment");
  }
  return *task;
}

// A recorded segment: its path against normalised time, and what was observed at its start.
SegmentTrajectory recorded(const std::string& name, const Eigen::MatrixXd& path,
                           Observation start) {
  return SegmentTrajectory{name, Eigen::VectorXd::LinSpaced(path.rows(), 0.0, 1.0), path,
                           Eigen::VectorXd(), std::move(start)};
}

}  // namespace

Demonstration ViaPointExpert::demonstrate(Environment& environment, const Scenario& scenario,
                                          bool) {
  ViaPoint& task = as_via_point(environment);
  const ViaPointParams& p = task.params();
  task.reset(scenario);
  Demonstration demo;
  demo.scenario = scenario_json(scenario);
  auto run = [&](const std::string& name, const Eigen::MatrixXd& path) {
    demo.segments.push_back(recorded(name, path, task.observe(false)));
    const std::string failure = task.execute(name, path);
    if (!failure.empty())
      throw std::runtime_error("the expert's " + name + "-MP failed: " + failure);
  };
  const Eigen::Vector2d start = task.effector_position().transpose();
  run("pre", straight_path(start, task.critical_point(), p.pre_points));
  demo.decision = task.decision_of(task.via_point().y() - task.critical_point().y());
  run("cor",
      bend_path(task.critical_point(), task.after_via(), task.via_point().y(), p.cor_points));
  run("post", straight_path(task.after_via(), task.goal(), p.post_points));

  // The whole skill walked at constant speed: each segment's span is its share of the length.
  Eigen::MatrixXd skill(0, 2);
  std::vector<double> lengths;
  for (const SegmentTrajectory& s : demo.segments) {
    const Eigen::Index skip = skill.rows() == 0 ? 0 : 1;  // a segment starts where the last ended
    Eigen::MatrixXd joined(skill.rows() + s.y.rows() - skip, 2);
    joined << skill, s.y.bottomRows(s.y.rows() - skip);
    skill = joined;
    lengths.push_back(path_length(s.y));
  }
  double total = 0.0, elapsed = 0.0;
  for (double length : lengths) total += length;
  for (size_t i = 0; i < lengths.size(); ++i) {
    demo.segments[i].phase_begin = elapsed / total;
    elapsed += lengths[i];
    demo.segments[i].phase_end = elapsed / total;
  }
  const int points = p.pre_points + p.cor_points + p.post_points;
  demo.segments.push_back(
      recorded("full", resample_by_length(skill, points), demo.segments.front().start));
  demo.segments.back().phase_begin = 0.0;
  demo.segments.back().phase_end = 1.0;
  return demo;
}

DemonstrationSplit ViaPointExpert::collect(Environment* environment, Rng& rng) {
  if (environment == nullptr) throw std::runtime_error("via_point_expert needs an environment");
  const ExpertCollection wanted{params_.train, params_.validation,
                                2 * (params_.train + params_.validation), "via_point_expert"};
  EnvironmentCopies environments(*environment, parallel_workers(wanted.max_attempts));
  return collect_expert_demonstrations(
      wanted, rng, environments.size(), [&](Rng& attempt_rng, int worker) {
        Environment& env = environments[worker];
        const Scenario scenario = env.sample_scenario(attempt_rng);
        Demonstration demo = demonstrate(env, scenario, false);
        const Outcome outcome = env.outcome();
        if (!outcome.success) {
          throw std::runtime_error(scenario_json(scenario) + ": " + outcome.failure);
        }
        return demo;
      });
}

}  // namespace corrmp
