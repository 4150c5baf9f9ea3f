// The emulated teleoperator of the knotting task (rope_expert.hpp).
#include "envs/rope_knot/rope_expert.hpp"

#include <fmt/format.h>

#include "core/thread_budget.hpp"
#include "data/expert_collection.hpp"
#include "envs/rope_knot/rope_knot_script.hpp"

namespace corrmp {

namespace {

RopeKnot& as_rope(Environment& environment) {
  auto* rope = dynamic_cast<RopeKnot*>(&environment);
  if (rope == nullptr)
    throw std::runtime_error("rope_expert demonstrates in a rope_knot environment");
  return *rope;
}

SegmentTrajectory segment_of(const std::string& name, const Eigen::MatrixXd& rows,
                             Observation start) {
  SegmentTrajectory s;
  s.segment = name;
  s.x = Eigen::VectorXd::LinSpaced(rows.rows(), 0.0, 1.0);
  s.y = rows;
  s.start = std::move(start);
  return s;
}

// The relative cor-MP: the task's relative columns as offsets from the first row.
Eigen::MatrixXd relative_to_start(const Eigen::MatrixXd& rows, const TaskReport& task) {
  Eigen::MatrixXd relative = rows;
  for (int c : task.relative_columns) relative.col(c).array() -= rows(0, c);
  return relative;
}

}  // namespace

Demonstration RopeExpert::demonstrate(Environment& environment, const Scenario& scenario,
                                      bool with_images) {
  RopeKnot& env = as_rope(environment);
  const RopeKnotParams& task = env.params().task;
  env.reset(scenario);
  Demonstration demo;
  demo.scenario = scenario_json(scenario);
  const auto run = [&](const std::string& name, const Eigen::MatrixXd& rows) {
    const std::string failure = env.execute(name, rows);
    if (!failure.empty()) {
      throw std::runtime_error(fmt::format("the expert's {}-MP failed: {}", name, failure));
    }
  };
  Observation initial = env.observe(with_images);
  const Eigen::MatrixXd pre = pre_waypoints(task);
  run("pre", pre);
  Observation critical = env.observe(with_images);
  const Eigen::Vector3d offset = correction_offset(env.scene());
  demo.decision = classify_rope_correction(offset, env.params().decision_threshold);
  const Eigen::MatrixXd cor = correction_waypoints(env.scene(), offset);
  const Eigen::MatrixXd cor_relative = relative_to_start(cor, env.report());
  run("cor", cor_relative);
  Observation after_correction = env.observe(with_images);
  const Eigen::MatrixXd post = post_waypoints(task, env.scene().left_command());
  run("post", post);

  demo.segments.push_back(segment_of("pre", pre, initial));
  demo.segments.push_back(segment_of("cor", cor_relative, std::move(critical)));
  demo.segments.push_back(segment_of("post", post, std::move(after_correction)));
  // The whole skill as one recording at the segments' rate; each segment's
  // span in it is kept for cutting a whole-skill policy at the critical points.
  const Eigen::Index total = pre.rows() + cor.rows() + post.rows();
  Eigen::MatrixXd full(total, 8);
  full << pre, cor, post;
  Eigen::Index begin = 0;
  for (auto& s : demo.segments) {
    s.phase_begin = static_cast<double>(begin) / static_cast<double>(total - 1);
    begin += s.y.rows();
    s.phase_end = static_cast<double>(begin - 1) / static_cast<double>(total - 1);
  }
  demo.segments.push_back(segment_of("full", full, std::move(initial)));
  demo.segments.back().phase_begin = 0.0;
  demo.segments.back().phase_end = 1.0;
  return demo;
}

DemonstrationSplit RopeExpert::collect(Environment* environment, Rng& rng) {
  if (environment == nullptr) throw std::runtime_error("rope_expert needs an environment");
  const ExpertCollection wanted{params_.train, params_.validation,
                                (params_.train + params_.validation) * params_.max_attempts_factor,
                                "rope_expert"};
  EnvironmentCopies environments(*environment, parallel_workers(wanted.max_attempts));
  return collect_expert_demonstrations(
      wanted, rng, environments.size(), [&](Rng& attempt_rng, int worker) {
        Environment& env = environments[worker];
        // Both draws every time, so the scenarios do not depend on the share.
        const bool nominal = attempt_rng.uniform() < params_.no_correction_share;
        const Scenario drawn = env.sample_scenario(attempt_rng);
        const Scenario scenario = nominal ? Scenario{} : drawn;
        Demonstration demo = demonstrate(env, scenario, params_.images);
        const Outcome outcome = env.outcome();
        if (!outcome.success) {
          throw std::runtime_error(scenario_json(scenario) + ": " + outcome.failure);
        }
        return demo;
      });
}

}  // namespace corrmp
