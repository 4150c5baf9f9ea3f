// Reader for demonstrations stored as CSV files, one file per demonstration: a header row naming
// the columns, then one comma-separated row of numbers per time step. The in-memory result has
// the same [T, D] layout as one slice of the [N, T, D] .npy arrays used by the public CNMP code
// of Seker et al. (RSS 2019).
#pragma once

#include <string>
#include <vector>

#include "cnmp/raw_trajectory.hpp"

namespace corrmp {

// Reads one demonstration. Fields may be surrounded by spaces or tabs; lines may end in "\n" or
// "\r\n"; blank lines are skipped. Throws DataError with a one-line "path:line: ..." message
// ("path: ..." when the file cannot be opened) for a missing file, an empty file or missing header,
// empty or duplicate column names, a ragged row, a field that is not a number, a NaN or infinite
// value, or a file without data rows.
RawTrajectory read_csv_trajectory(const std::string& path);

// Reads several demonstrations (in the given order) and checks that all files have the same
// columns in the same order. An empty list gives an empty result.
std::vector<RawTrajectory> read_csv_trajectories(const std::vector<std::string>& paths);

}  // namespace corrmp
