// Researchers' own demonstrations as CNMP training data: .npy arrays [N, T, D]
// (the public CNMP code's format) or CSV files (one per demonstration), with the
// columns that form the CNMP's x (time, normalised to [0, 1], plus task
// parameters), y and context chosen by name. Paper, Section III-A.
#pragma once

#include <string>
#include <vector>

#include "cnmp/cnmp_trainer.hpp"
#include "cnmp/raw_trajectory.hpp"

namespace corrmp {

struct TrajectoryColumns {
  std::string time;                  // "" : time is the step index
  std::vector<std::string> inputs;   // task parameters appended to x after time
  std::vector<std::string> outputs;  // y
  std::vector<std::string> context;  // constant within a trajectory
};

// The files `paths` names, directories expanded into the .npy and .csv files they hold (sorted
// by name). Throws DataError for a missing path, a directory without such files or a file of
// another kind.
std::vector<std::string> list_trajectory_files(const std::vector<std::string>& paths);

// Reads every file list_trajectory_files lists. Throws DataError for missing paths and bad
// files.
std::vector<RawTrajectory> read_trajectory_files(const std::vector<std::string>& paths);

// What the roles of columns are called where they were chosen (options, config keys), for
// messages.
struct ColumnRoleNames {
  std::string time = "time_column", inputs = "input_columns", outputs = "output_columns",
              context = "context_columns";
};

// Throws DataError "<role>: column 'c' is named twice" for a column named twice in one role,
// or "<role>: column 'c' is also named by <other role>; ..." for one given two roles (an output
// that is also the time or an input would be learnt from itself). Needs no data.
void check_column_roles(const TrajectoryColumns& columns, const ColumnRoleNames& names = {});

// Checks the columns' roles (check_column_roles), selects and checks the columns; x column 0 is
// time normalised per trajectory to [0, 1]. Throws DataError naming the trajectory for unknown
// columns, a time column that does not increase, a context that varies within a trajectory, or
// fewer than 2 time steps.
std::vector<CnmpTrajectory> select_columns(const std::vector<RawTrajectory>& raw,
                                           const TrajectoryColumns& columns);

}  // namespace corrmp
