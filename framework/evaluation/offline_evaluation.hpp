// Offline evaluation of a trained policy on held-out demonstrations: each
// segment is generated from the demonstration's own start point and context
// and compared with the demonstration (the paper's Table II error: Euclidean
// distance averaged over time points; mean and max over demonstrations).
#pragma once

#include <string>
#include <vector>

#include "data/demonstrations.hpp"
#include "evaluation/trajectory_error.hpp"
#include "policies/policy.hpp"

namespace corrmp {

struct SegmentErrors {
  std::string segment;
  TrajectoryError error;
};

// Errors per segment; with a non-empty `csv_directory`, also writes
// <segment>.csv there (demonstration, step, x, demonstrated y, predicted mean and std).
std::vector<SegmentErrors> evaluate_offline(Policy& policy,
                                            const std::vector<Demonstration>& demonstrations,
                                            const std::string& csv_directory);

}  // namespace corrmp
