// A simulated task cut into segments at its critical points (paper, Section
// III): it draws scenarios, resets to one, executes segment trajectories of its
// effector, reports observations at segment starts and the trial's outcome.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/seeds.hpp"
#include "envs/observation.hpp"

namespace corrmp {

struct SegmentInfo {
  std::string name;
  int points = 50;  // trajectory points of the segment in demonstrations
};

struct Outcome {
  bool success = false;
  std::string failure;  // the reason when not successful
};

class Environment {
 public:
  virtual ~Environment() = default;

  virtual Scenario sample_scenario(Rng& rng) const = 0;
  virtual void reset(const Scenario& scenario) = 0;

  // The segments of the skill in execution order.
  virtual std::vector<SegmentInfo> segments() const = 0;

  // The effector's current position (the start of the next segment).
  virtual Eigen::RowVectorXd effector_position() const = 0;
  // Tracks a segment trajectory (rows: effector positions). Returns "" on
  // success or why execution stopped (a physics blow-up, an invalid point).
  virtual std::string execute(const Eigen::MatrixXd& trajectory) = 0;
  virtual Observation observe(bool with_image) = 0;
  virtual Outcome outcome() const = 0;

  // The kind of correction a cor-MP trajectory performs (push, pull, none), for
  // the paper's Table I; "" when the task has no such notion.
  virtual std::string classify_correction(const Eigen::MatrixXd& trajectory) const = 0;
};

}  // namespace corrmp
