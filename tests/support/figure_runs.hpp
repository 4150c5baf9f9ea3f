// Test helper: run summaries and small run directories (a corridor-like
// trajectories.csv, the trials' decisions) for the reproduction figures' tests.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "config/test_files.hpp"
#include "report/reproduction_figures.hpp"

namespace corrmp::testing {

// The size of the PNG at `path`, or 0 x 0 when it cannot be read.
inline cv::Size png_size(const std::string& path) {
  const cv::Mat image = cv::imread(path);
  return image.empty() ? cv::Size() : image.size();
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Whether a note of the figure set mentions `part`.
inline bool any_note(const FigureSet& set, const std::string& part) {
  return std::any_of(set.notes.begin(), set.notes.end(),
                     [&](const std::string& note) { return contains(note, part); });
}

inline RunSummary run_of(int64_t id, const std::string& experiment,
                         std::map<std::string, std::string> axes, std::optional<double> success) {
  RunSummary run;
  run.id = id;
  run.experiment = experiment;
  run.status = RunStatus::completed;
  run.axes = std::move(axes);
  if (success) run.metrics["task_success_rate"] = *success;
  return run;
}

// What write_trajectories writes of the executed path.
enum class ExecutedColumns {
  none,    // no executed_ columns, as files written before executions were recorded
  empty,   // the columns, every field empty (a task that records no execution)
  values,  // 3 mm beside the generated path in y; trial 1's last post step not executed
};

// A corridor run directory: trajectories.csv with trials 0 (push), 1 (pull)
// and 2 (push), segments pre, cor and post of 4 steps each.
inline void write_trajectories(const TempDir& dir, const std::string& run,
                               ExecutedColumns executed = ExecutedColumns::none) {
  std::string csv = "trial,segment,step,x,y,z,expert_x,expert_y,expert_z";
  csv += executed == ExecutedColumns::none ? "\n" : ",executed_x,executed_y,executed_z\n";
  for (int trial = 0; trial < 3; ++trial) {
    for (const std::string segment : {"cor", "post", "pre"}) {  // as the evaluation writes them
      for (int step = 0; step < 4; ++step) {
        const double x = 0.4 + 0.01 * step, y = -0.1 + 0.02 * step + 0.01 * trial;
        csv += fmt::format("{},{},{},{},{},0.03,{},{},0.03", trial, segment, step, x, y, x + 0.002,
                           y - 0.001);
        const bool reached = !(trial == 1 && segment == "post" && step == 3);
        if (executed == ExecutedColumns::values && reached) {
          csv += fmt::format(",{},{},0.03", x, y + 0.003);
        } else if (executed != ExecutedColumns::none) {
          csv += ",,,";
        }
        csv += "\n";
      }
    }
  }
  dir.write(run + "/trajectories.csv", csv);
}

// The run files of the directory `run` with the trials above.
inline RunFiles files_in(const TempDir& dir, const std::string& run) {
  RunFiles files;
  files.recorded = files.directory = dir.file(run);
  files.trials = {
      {0, "push", "push", true}, {1, "pull", "push", false}, {2, "push", "push", false}};
  return files;
}

}  // namespace corrmp::testing
