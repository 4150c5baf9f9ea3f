// Recorded demonstrations from files, read at load and split into training and validation.
#include "cnmp/trajectory_files.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "core/config/config_error.hpp"
#include "core/json_writer.hpp"
#include "core/parameter_error.hpp"

namespace corrmp {

namespace {

namespace fs = std::filesystem;

void check_paths_exist(const TrajectoryFilesParams& params) {
  for (const auto& path : params.paths) {
    std::error_code error;
    if (fs::exists(path, error)) continue;
    throw ConfigError(fmt::format(
        "demonstrations.paths: '{}' does not exist (relative paths are taken from the folder "
        "the program runs in, {})",
        path, fs::current_path().string()));
  }
}

std::vector<RawTrajectory> read_files(const std::vector<std::string>& paths) {
  if (paths.empty()) throw ParameterError("paths", "no demonstration files given");
  try {
    return read_trajectory_files(paths);
  } catch (const DataError& e) {
    throw ParameterError("paths", e.what());
  } catch (const fs::filesystem_error& e) {  // e.g. a directory that cannot be listed
    throw ParameterError("paths", fmt::format("{}: {}", e.path1().string(), e.code().message()));
  }
}

}  // namespace

std::vector<LoadedTrajectory> load_trajectory_files(const TrajectoryFilesParams& params) {
  check_paths_exist(params);
  const std::vector<RawTrajectory> raw = read_files(params.paths);
  std::vector<CnmpTrajectory> selected;
  try {
    selected = select_columns(raw, {params.time_column, params.input_columns, params.output_columns,
                                    params.context_columns});
  } catch (const DataError& e) {
    throw std::invalid_argument(e.what());
  }
  std::vector<LoadedTrajectory> loaded;
  loaded.reserve(selected.size());
  for (size_t i = 0; i < selected.size(); ++i) {
    loaded.push_back({raw[i].source, std::move(selected[i])});
  }
  return loaded;
}

DemonstrationSplit TrajectoryFiles::collect(Environment*, Rng& rng) {
  std::vector<size_t> order(trajectories_.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  for (size_t i = order.size(); i > 1; --i) {
    std::swap(order[i - 1], order[static_cast<size_t>(rng.uniform_int(0, i - 1))]);
  }
  const auto validation =
      static_cast<size_t>(std::floor(params_.validation_fraction * trajectories_.size()));
  DemonstrationSplit split;
  for (size_t k = 0; k < order.size(); ++k) {
    const LoadedTrajectory& loaded = trajectories_[order[k]];
    const CnmpTrajectory& t = loaded.trajectory;
    Demonstration demo{JsonObject().add("source", loaded.source).str(),
                       {SegmentTrajectory{params_.segment, t.x, t.y, t.context, Observation{}}},
                       ""};
    (k < validation ? split.validation : split.train).push_back(std::move(demo));
  }
  if (split.train.empty()) throw DataError("no demonstrations left for training");
  return split;
}

}  // namespace corrmp
