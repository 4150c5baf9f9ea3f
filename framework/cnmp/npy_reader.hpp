// Reader for demonstrations stored as NumPy .npy files, the format of the public CNMP code of
// Seker et al. (RSS 2019): one float array of shape [N, T, D] holding N demonstrations of T time
// steps and D dimensions each.
#pragma once

#include <string>
#include <vector>

#include "cnmp/raw_trajectory.hpp"

namespace corrmp {

// Reads a .npy file (format versions 1.0, 2.0 and 3.0) holding a C-ordered little-endian
// float32 ('<f4') or float64 ('<f8') array of shape [N, T, D]. Returns one RawTrajectory per
// demonstration, with columns "c0".."c{D-1}" and sources "path[n]". Throws DataError, with a
// one-line message starting with "path: ", for a missing or malformed file, an unsupported
// dtype, layout or shape (a 2-D array too: [T, D] of one demonstration and [N, T] of one-column
// ones cannot be told apart, so the message says how to save either as [N, T, D]), an empty
// dimension, truncated data, or a NaN / infinite value.
std::vector<RawTrajectory> read_npy_trajectories(const std::string& path);

}  // namespace corrmp
