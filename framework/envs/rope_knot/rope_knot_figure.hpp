// The paper's knotting figure (Section IV-C, "Real robot knotting
// performance"), from a run's data: left, the correction demonstrations
// (the left gripper's cor-MP displacement, grey) with the corrections the
// policy generated in the test trials over them; right, the contexts (the
// rope end relative to the gripper mid-point): training grey, successful
// tests green, failures coloured by category. Both panels are top views:
// lateral y to the right, posterior-anterior x up, in cm.
#pragma once

#include <string>
#include <vector>

#include "data/demonstrations.hpp"
#include "data/evaluated_trial.hpp"

namespace corrmp {

// Throws std::runtime_error naming the path when it cannot be written.
void write_knotting_figure(const std::vector<EvaluatedTrial>& trials,
                           const std::vector<Demonstration>& train, const std::string& png_path);

}  // namespace corrmp
