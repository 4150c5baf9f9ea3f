// Error reporting for the shape checks of nn/check.hpp.
#include "nn/check.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace corrmp::nn {

void throw_shape_error(const char* where, const char* what, Index rows, Index cols,
                       Index expected_rows, Index expected_cols) {
  throw std::invalid_argument(fmt::format("{}: {} is {}x{}, expected {}x{}", where, what, rows,
                                          cols, expected_rows, expected_cols));
}

}  // namespace corrmp::nn
