// A simulated task cut into segments at its critical points (paper, Section
// III): it draws scenarios, resets to one, executes segment trajectories of its
// effectors, reports observations at segment starts and the trial's outcome.
// A task also declares what it reports (TaskReport): the generic evaluation,
// tables, database rows and figures loop over that and know no task by name
// (docs/architecture.md, "Adding a task").
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/metric.hpp"
#include "core/seeds.hpp"
#include "core/task_declaration.hpp"
#include "data/demonstrations.hpp"
#include "data/evaluated_trial.hpp"
#include "data/observation.hpp"

namespace corrmp {

struct SegmentInfo {
  std::string name;
  int points = 50;  // trajectory points of the segment in demonstrations
  // Rows are offsets from the effectors' positions at the segment's start (a
  // correction "relative to the gripper", paper Section IV-C), not positions.
  bool relative = false;
};

struct Outcome {
  bool success = false;
  std::string failure;  // the reason (or failure category) when not successful
  // The task's named outcome measurements (TaskReport::outcome_metrics), each
  // averaged over the trials into the run metric <name>_rate.
  std::map<std::string, double> metrics;
  // Further values of this trial kept in its database row (not averaged),
  // such as the true rope-end offset at the critical point.
  std::map<std::string, double> details;
};

// What a task reports (core/task_declaration.hpp); the result store keeps it with each run.
using TaskReport = TaskDeclaration;

// TaskReport::relative_columns, or every column of a `width`-column row.
inline std::vector<int> relative_columns_of(const TaskReport& task, Eigen::Index width) {
  if (!task.relative_columns.empty()) return task.relative_columns;
  std::vector<int> all(static_cast<size_t>(width));
  for (Eigen::Index c = 0; c < width; ++c) all[static_cast<size_t>(c)] = static_cast<int>(c);
  return all;
}

class Environment {
 public:
  virtual ~Environment() = default;

  // A new environment with the same parameters, in the state after
  // construction, for another thread (Bullet worlds cannot be shared): experts
  // collect their demonstrations with one environment per thread. Null when
  // the task cannot make one; its experts then collect on one thread.
  virtual std::unique_ptr<Environment> clone() const { return nullptr; }

  virtual TaskReport report() const = 0;

  virtual Scenario sample_scenario(Rng& rng) const = 0;
  virtual void reset(const Scenario& scenario) = 0;

  // The segments of the skill in execution order.
  virtual std::vector<SegmentInfo> segments() const = 0;

  // The effectors' current positions (one row, trajectory columns): where the
  // next absolute segment starts.
  virtual Eigen::RowVectorXd effector_position() const = 0;
  // The first row of `segment`'s trajectory from the current state: the
  // effectors' positions, with zero offsets in the relative columns of a
  // relative segment.
  virtual Eigen::RowVectorXd segment_start(const std::string& segment) const {
    Eigen::RowVectorXd start = effector_position();
    for (const auto& s : segments()) {
      if (s.name == segment && s.relative) {
        for (int c : relative_columns_of(report(), start.size())) start(c) = 0.0;
      }
    }
    return start;
  }
  // Tracks the trajectory of `segment` (rows: trajectory columns; offsets
  // when the segment is relative; a segment the task does not list, such as
  // a whole-skill "full", is absolute). Returns "" on success or why
  // execution stopped (a physics blow-up, an invalid point).
  virtual std::string execute(const std::string& segment, const Eigen::MatrixXd& trajectory) = 0;
  // Where the effectors actually were during the last execute(): per
  // trajectory row the command reached, in order, the row of the effectors'
  // positions then, in the trajectory's columns and frame (offsets in the
  // relative columns of a relative segment). Rows stop where execution
  // stopped. Empty when the task does not record it.
  virtual Eigen::MatrixXd executed_path() const { return {}; }
  virtual Observation observe(bool with_image) = 0;
  // The size of the images observe(true) takes; empty without a camera.
  virtual cv::Size camera_size() const { return {}; }
  // The names of the state values every observation holds (checked at load
  // against what the context extractor reads).
  virtual std::vector<std::string> state_names() const = 0;
  virtual Outcome outcome() const = 0;

  // The decision a trajectory of TaskReport::decision_segment performs (one
  // of the declared labels); "" when the task has no decision.
  virtual std::string classify_decision(const Eigen::MatrixXd&) const { return ""; }

  // Writes the task's own figures of an evaluation into the run directory
  // (the generic trajectories figure is written besides).
  virtual void write_figures(const std::string& /*directory*/,
                             const std::vector<EvaluatedTrial>& /*trials*/,
                             const std::vector<Demonstration>& /*train*/) const {}

  // What the task measures of an evaluation beyond what it declares: run metrics made from
  // the trials alone (so the same trials give the same metrics) and lines for the run's log
  // (headed "... (<label>)"), which may show wall-clock figures that no result or table keeps.
  struct RunAdditions {
    std::vector<Metric> metrics;
    std::string log;
  };
  virtual RunAdditions run_additions(const std::vector<EvaluatedTrial>& /*trials*/,
                                     const std::string& /*label*/) const {
    return {};
  }
};

// Environments for up to `workers` threads: `first` and clones of it (only
// `first` when it cannot be cloned). Clones are made at construction, on the
// calling thread.
class EnvironmentCopies {
 public:
  EnvironmentCopies(Environment& first, int workers) : first_(first) {
    for (int w = 1; w < workers; ++w) {
      std::unique_ptr<Environment> copy = first.clone();
      if (!copy) break;
      copies_.push_back(std::move(copy));
    }
  }
  int size() const { return static_cast<int>(copies_.size()) + 1; }
  Environment& operator[](int worker) {
    return worker == 0 ? first_ : *copies_.at(static_cast<size_t>(worker - 1));
  }

 private:
  Environment& first_;
  std::vector<std::unique_ptr<Environment>> copies_;
};

}  // namespace corrmp
