// What the closed-loop evaluation writes for plotting (paper, Fig. 6: ground
// truth, prediction and robot execution): every generated, expert and executed
// trajectory as CSV, and a figure with one top-view panel per trial.
#pragma once

#include <string>
#include <vector>

#include "data/evaluated_trial.hpp"
#include "envs/environment.hpp"

namespace corrmp {

// Columns trial, segment, step, then the task's trajectory columns as
// generated, then the same prefixed expert_, then prefixed executed_ (empty
// fields in the rows the execution did not reach), in world coordinates (a
// relative segment's offsets are added to where it started).
void write_trajectory_csv(const std::vector<EvaluatedTrial>& trials, const TaskReport& task,
                          const std::string& path);

// kTrajectoryColumns panels per row, each kTrajectoryPanelWidth x
// kTrajectoryPanelHeight under a kTrajectoryHeader-pixel caption: the task's
// plot columns (TaskReport::plot_vertical against plot_horizontal) in world
// coordinates, all panels on the same axes; the expert's path thick and grey
// beneath the generated one, coloured by the segment's place in
// `segment_order` (blue, orange, green, ...), the executed path (if any)
// thin and dashed over it in a darker shade of that colour, as the caption
// says; the title names the trial, the expected and chosen decisions and
// whether it succeeded.
constexpr int kTrajectoryColumns = 5;
constexpr int kTrajectoryPanelWidth = 300;
constexpr int kTrajectoryPanelHeight = 220;
constexpr int kTrajectoryHeader = 30;
void write_trajectory_figure(const std::vector<EvaluatedTrial>& trials, const TaskReport& task,
                             const std::vector<std::string>& segment_order,
                             const std::string& png_path);

}  // namespace corrmp
