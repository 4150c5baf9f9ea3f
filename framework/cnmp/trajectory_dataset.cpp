// Reading researchers' demonstration files into CNMP trajectories.
#include "cnmp/trajectory_dataset.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "cnmp/csv_reader.hpp"
#include "cnmp/npy_reader.hpp"

namespace corrmp {

namespace fs = std::filesystem;

namespace {

bool is_data_file(const fs::path& path) {
  return path.extension() == ".npy" || path.extension() == ".csv";
}

int column_index(const RawTrajectory& raw, const std::string& name) {
  const auto it = std::find(raw.columns.begin(), raw.columns.end(), name);
  if (it == raw.columns.end()) {
    throw DataError(fmt::format("{}: no column '{}' (columns: {})", raw.source, name,
                                fmt::join(raw.columns, ", ")));
  }
  return static_cast<int>(it - raw.columns.begin());
}

}  // namespace

std::vector<std::string> list_trajectory_files(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const auto& path : paths) {
    if (fs::is_directory(path)) {
      std::vector<std::string> inside;
      for (const auto& entry : fs::directory_iterator(path)) {
        if (entry.is_regular_file() && is_data_file(entry.path())) {
          inside.push_back(entry.path().string());
        }
      }
      if (inside.empty()) throw DataError(path + ": no .npy or .csv files in this directory");
      std::sort(inside.begin(), inside.end());
      files.insert(files.end(), inside.begin(), inside.end());
    } else if (!fs::exists(path)) {
      throw DataError(path + ": no such file or directory");
    } else if (!is_data_file(path)) {
      throw DataError(path + ": expected a .npy or .csv file");
    } else {
      files.push_back(path);
    }
  }
  return files;
}

std::vector<RawTrajectory> read_trajectory_files(const std::vector<std::string>& paths) {
  const std::vector<std::string> files = list_trajectory_files(paths);
  std::vector<RawTrajectory> raw;
  std::vector<std::string> csv_files;
  for (const auto& file : files) {
    if (fs::path(file).extension() == ".npy") {
      for (auto& t : read_npy_trajectories(file)) raw.push_back(std::move(t));
    } else {
      csv_files.push_back(file);
    }
  }
  for (auto& t : read_csv_trajectories(csv_files)) raw.push_back(std::move(t));
  return raw;
}

void check_column_roles(const TrajectoryColumns& columns, const ColumnRoleNames& names) {
  std::map<std::string, const std::string*> role_of;  // column -> the role that named it first
  const auto claim = [&](const std::string& column, const std::string& role) {
    const auto [it, first] = role_of.emplace(column, &role);
    if (first) return;
    throw DataError(*it->second == role
                        ? fmt::format("{}: column '{}' is named twice", role, column)
                        : fmt::format("{}: column '{}' is also named by {}; each column has one "
                                      "role",
                                      role, column, *it->second));
  };
  if (!columns.time.empty()) claim(columns.time, names.time);
  for (const auto& column : columns.inputs) claim(column, names.inputs);
  for (const auto& column : columns.outputs) claim(column, names.outputs);
  for (const auto& column : columns.context) claim(column, names.context);
}

std::vector<CnmpTrajectory> select_columns(const std::vector<RawTrajectory>& raw,
                                           const TrajectoryColumns& columns) {
  if (columns.outputs.empty()) throw DataError("no output (y) columns chosen");
  check_column_roles(columns);
  std::vector<CnmpTrajectory> out;
  for (const RawTrajectory& r : raw) {
    const Eigen::Index steps = r.values.rows();
    if (steps < 2) throw DataError(fmt::format("{}: needs at least 2 time steps", r.source));
    CnmpTrajectory t;
    t.x.resize(steps, 1 + static_cast<Eigen::Index>(columns.inputs.size()));
    if (columns.time.empty()) {
      for (Eigen::Index i = 0; i < steps; ++i) t.x(i, 0) = static_cast<double>(i) / (steps - 1);
    } else {
      const Eigen::VectorXd time = r.values.col(column_index(r, columns.time));
      for (Eigen::Index i = 1; i < steps; ++i) {
        if (!(time[i] > time[i - 1])) {
          throw DataError(fmt::format("{}: time column '{}' does not increase at step {}", r.source,
                                      columns.time, i));
        }
      }
      t.x.col(0) = (time.array() - time[0]) / (time[steps - 1] - time[0]);
    }
    for (size_t i = 0; i < columns.inputs.size(); ++i) {
      t.x.col(1 + i) = r.values.col(column_index(r, columns.inputs[i]));
    }
    t.y.resize(steps, static_cast<Eigen::Index>(columns.outputs.size()));
    for (size_t i = 0; i < columns.outputs.size(); ++i) {
      t.y.col(i) = r.values.col(column_index(r, columns.outputs[i]));
    }
    t.context.resize(static_cast<Eigen::Index>(columns.context.size()));
    for (size_t i = 0; i < columns.context.size(); ++i) {
      const Eigen::VectorXd values = r.values.col(column_index(r, columns.context[i]));
      if ((values.array() != values[0]).any()) {
        throw DataError(fmt::format("{}: context column '{}' varies within the trajectory",
                                    r.source, columns.context[i]));
      }
      t.context[i] = values[0];
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace corrmp
