// Demonstration source `trajectory_files`: a researcher's recorded
// demonstrations (.npy or CSV) as one-segment demonstrations, split at random
// (from the component's seed stream) into training and validation sets.
#pragma once

#include <string>
#include <vector>

#include "cnmp/trajectory_dataset.hpp"
#include "core/config/field_rule.hpp"
#include "data/demonstrations.hpp"

namespace corrmp {

struct TrajectoryFilesParams {
  std::vector<std::string> paths;
  std::string time_column;
  std::vector<std::string> input_columns;
  std::vector<std::string> output_columns;
  std::vector<std::string> context_columns;
  double validation_fraction = 0.2;
  std::string segment = "full";

  template <class Fields>
  void describe(Fields& f) {
    f("paths", paths, ".npy files, .csv files or directories of them", required());
    f("time_column", time_column, "column holding time ('' : the step index)");
    f("input_columns", input_columns, "task parameters appended to the CNMP input after time");
    f("output_columns", output_columns, "the trajectory columns the CNMP learns", required());
    f("context_columns", context_columns, "columns holding the (constant) context");
    f("validation_fraction", validation_fraction, "share of demonstrations held out",
      in_range(0.0, 0.9));
    f("segment", segment, "segment name given to every demonstration");
  }
};

/// Throws ConfigError naming the first of `params.paths` that does not exist, so that a run
/// is refused (exit 2, nothing recorded) before it starts; the files' contents are checked
/// when they are read. Relative paths are taken from the current folder.
void check_trajectory_paths(const TrajectoryFilesParams& params);

class TrajectoryFiles : public DemonstrationSource {
 public:
  explicit TrajectoryFiles(const TrajectoryFilesParams& params) : params_(params) {}
  DemonstrationSplit collect(Environment* environment, Rng& rng) override;
  std::vector<std::string> segments() const override { return {params_.segment}; }
  bool provides_contexts() const override { return !params_.context_columns.empty(); }

 private:
  TrajectoryFilesParams params_;
};

}  // namespace corrmp
