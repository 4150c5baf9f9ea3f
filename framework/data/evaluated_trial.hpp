// One closed-loop evaluation trial as the generic evaluation saw it (paper,
// Section IV-B): the scenario, what the policy generated, what was executed
// and what the expert demonstrated for each segment, the contexts the policy was
// given, the decision and the outcome. Figures and the trial rows are drawn from these.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>

#include "data/observation.hpp"

namespace corrmp {

struct EvaluatedTrial {
  int trial = 0;
  Scenario scenario;
  bool success = false;
  std::string failure;  // "" on success
  std::string expected_action, chosen_action;
  // Per segment, in the segment's own frame (offsets for relative segments).
  std::map<std::string, Eigen::MatrixXd> generated, expert;
  // Per segment, in the same frame: where the effectors were when the
  // execution reached each generated row (Environment::executed_path), as
  // many rows as were executed; no entry when the task does not record it.
  std::map<std::string, Eigen::MatrixXd> executed;
  // The effectors' positions where each relative segment started (add them to
  // the segment's position columns for world coordinates).
  std::map<std::string, Eigen::RowVectorXd> origins;
  std::map<std::string, Eigen::VectorXd> contexts;  // as the policy was given them
  std::map<std::string, double> outcome;            // the task's outcome metrics
  std::map<std::string, double> details;            // the task's further values
};

}  // namespace corrmp
