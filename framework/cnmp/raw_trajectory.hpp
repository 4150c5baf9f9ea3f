// A demonstration trajectory as read from a user's data file, before it is split into CNMP
// inputs/outputs, and the error every demonstration loader throws on bad data.
//
// The public CNMP code of Seker et al. (RSS 2019) stores demonstrations as NumPy .npy arrays of
// shape [N, T, D] (N demonstrations, T time steps, D dimensions); one RawTrajectory holds one of
// those N slices, or the contents of one CSV file.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

namespace corrmp {

struct RawTrajectory {
  std::string source;                // file (and index for .npy: "demos.npy[3]") for messages
  std::vector<std::string> columns;  // column names
  Eigen::MatrixXd values;            // T x D, row t = time step t
};

// Bad or unreadable demonstration data; what() is a single line starting with the file path.
class DataError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace corrmp
