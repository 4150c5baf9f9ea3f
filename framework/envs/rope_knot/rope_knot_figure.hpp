// The paper's knotting figure (Section IV-C, "Real robot knotting
// performance"), from a run's data: left, the correction demonstrations
// (the left gripper's cor-MP displacement, grey) with the corrections the
// policy generated in the test trials over them; right, the contexts (the
// rope end relative to the gripper mid-point): training grey, successful
// tests green, failures coloured by their category (the first declared
// category their reason starts with; others "other"), with a legend of the
// categories that occur. Both panels are top views: lateral y to the right,
// posterior-anterior x up, in cm.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "data/demonstrations.hpp"
#include "data/evaluated_trial.hpp"

namespace corrmp {

// `categories`: the task's failure categories (TaskReport::failure_categories), in their
// declared order. Throws std::runtime_error naming the path when it cannot be written.
void write_knotting_figure(const std::vector<EvaluatedTrial>& trials,
                           const std::vector<Demonstration>& train,
                           const std::vector<std::string>& categories, const std::string& png_path);

// A colour of the figure (BGR) and what it shows.
struct KnottingLegendEntry {
  std::string text;
  cv::Scalar colour;
};

// The colour of a test trial: green when it succeeded, else that of its failure's category
// (each category its own, by its place in `categories`), or that of "other".
cv::Scalar knotting_trial_colour(const EvaluatedTrial& trial,
                                 const std::vector<std::string>& categories);

// The legend's failure entries: each category some failed trial falls in, in the declared
// order, then "other" when a failure falls in none.
std::vector<KnottingLegendEntry> knotting_failure_legend(
    const std::vector<EvaluatedTrial>& trials, const std::vector<std::string>& categories);

}  // namespace corrmp
