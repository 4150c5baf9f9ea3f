// Cheap argument checks for corrmp::nn: a shape mismatch throws std::invalid_argument with a
// one-line message instead of corrupting memory in a Release build.
#pragma once

#include "nn/tensor.hpp"

namespace corrmp::nn {

/// Throws std::invalid_argument "<where>: <what> is RxC, expected ErxEc".
[[noreturn]] void throw_shape_error(const char* where, const char* what, Index rows, Index cols,
                                    Index expected_rows, Index expected_cols);

/// Checks that a matrix argument has the expected shape.
template <class Derived>
inline void check_shape(const char* where, const char* what, const Eigen::DenseBase<Derived>& m,
                        Index expected_rows, Index expected_cols) {
  if (m.rows() != expected_rows || m.cols() != expected_cols)
    throw_shape_error(where, what, m.rows(), m.cols(), expected_rows, expected_cols);
}

}  // namespace corrmp::nn
