// What the closed-loop evaluation writes for plotting (paper, Fig. 6: generated
// trajectories against the ground truth): every generated and expert
// trajectory as CSV, and a figure with one top-view panel per trial.
#pragma once

#include <string>
#include <vector>

#include "experiment/environment_evaluation.hpp"

namespace corrmp {

// Columns trial, segment, step, x, y, z, expert_x, expert_y, expert_z.
void write_trajectory_csv(const std::vector<TrialTrajectories>& trials, const std::string& path);

// kTrajectoryColumns panels per row, each kTrajectoryPanelWidth x
// kTrajectoryPanelHeight under a kTrajectoryHeader-pixel caption: the
// gripper's x (vertical) against y (horizontal), all panels on the same axes;
// the expert's path thick and grey beneath the generated one, coloured by
// segment (pre blue, cor orange, post green); the title names the trial, the
// expected and chosen corrections and whether it succeeded.
constexpr int kTrajectoryColumns = 5;
constexpr int kTrajectoryPanelWidth = 300;
constexpr int kTrajectoryPanelHeight = 220;
constexpr int kTrajectoryHeader = 30;
void write_trajectory_figure(const std::vector<TrialTrajectories>& trials,
                             const std::string& png_path);

}  // namespace corrmp
