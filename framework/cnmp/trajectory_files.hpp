// Demonstration source `trajectory_files`: a researcher's recorded
// demonstrations (.npy or CSV), read and checked when the config is loaded, as
// one-segment demonstrations, split at random (from the component's seed
// stream) into training and validation sets.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "cnmp/trajectory_dataset.hpp"
#include "core/config/field_rule.hpp"
#include "envs/demonstration_source.hpp"

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

/// One demonstration as a run uses it, and where it came from ("demos.npy[3]", "a.csv").
struct LoadedTrajectory {
  std::string source;
  CnmpTrajectory trajectory;
};

/// Reads `params.paths` and selects the columns with the readers train_cnmp uses, so that bad
/// demonstrations refuse a run (exit 2, nothing recorded) before it starts. Throws ConfigError
/// naming the first path that does not exist (relative paths are taken from the current folder);
/// ParameterError at `paths` for a file the readers refuse (NaN, a ragged row, a bad .npy header,
/// ...; the message names the file, and the line where the reader knows it); and
/// std::invalid_argument for a column a file lacks, a time column that does not increase or a
/// varying context (core/registry.hpp turns both into ConfigErrors at the config's line).
std::vector<LoadedTrajectory> load_trajectory_files(const TrajectoryFilesParams& params);

class TrajectoryFiles : public DemonstrationSource {
 public:
  /// `trajectories`: the files' contents, from load_trajectory_files(params).
  TrajectoryFiles(const TrajectoryFilesParams& params, std::vector<LoadedTrajectory> trajectories)
      : params_(params), trajectories_(std::move(trajectories)) {}
  DemonstrationSplit collect(Environment* environment, Rng& rng) override;
  std::vector<std::string> segments() const override { return {params_.segment}; }
  bool provides_contexts() const override { return !params_.context_columns.empty(); }

 private:
  TrajectoryFilesParams params_;
  std::vector<LoadedTrajectory> trajectories_;
};

}  // namespace corrmp
