// Recorded demonstrations from files, split into training and validation.
#include "cnmp/trajectory_files.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "core/config/config_error.hpp"
#include "core/json_writer.hpp"

namespace corrmp {

void check_trajectory_paths(const TrajectoryFilesParams& params) {
  namespace fs = std::filesystem;
  for (const auto& path : params.paths) {
    std::error_code error;
    if (fs::exists(path, error)) continue;
    throw ConfigError(fmt::format(
        "demonstrations.paths: '{}' does not exist (relative paths are taken from the folder "
        "the program runs in, {})",
        path, fs::current_path().string()));
  }
}

DemonstrationSplit TrajectoryFiles::collect(Environment*, Rng& rng) {
  const auto raw = read_trajectory_files(params_.paths);
  const auto trajectories = select_columns(raw, {params_.time_column, params_.input_columns,
                                                 params_.output_columns, params_.context_columns});
  std::vector<size_t> order(trajectories.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  for (size_t i = order.size(); i > 1; --i) {
    std::swap(order[i - 1], order[static_cast<size_t>(rng.uniform_int(0, i - 1))]);
  }
  const auto validation =
      static_cast<size_t>(std::floor(params_.validation_fraction * trajectories.size()));
  DemonstrationSplit split;
  for (size_t k = 0; k < order.size(); ++k) {
    const auto& t = trajectories[order[k]];
    Demonstration demo{JsonObject().add("source", raw[order[k]].source).str(),
                       {SegmentTrajectory{params_.segment, t.x, t.y, t.context, Observation{}}},
                       ""};
    (k < validation ? split.validation : split.train).push_back(std::move(demo));
  }
  if (split.train.empty()) throw DataError("no demonstrations left for training");
  return split;
}

}  // namespace corrmp
