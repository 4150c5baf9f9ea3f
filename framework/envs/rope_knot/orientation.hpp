// Exact orientation of three points in the plane, whatever the compiler contracts.
#pragma once

#include <Eigen/Core>

namespace corrmp {

// Sign of the determinant | b - a, c - a | for the given doubles, computed exactly: +1 when
// a, b, c turn counter-clockwise, -1 clockwise, 0 when exactly collinear. A floating-point
// filter answers most calls; the rest sum the six products of the expanded determinant
// exactly (error-free products and sums). Exact unless a product underflows or overflows
// (non-zero coordinates below about 1e-150 or above about 1e150 in magnitude; the knot check's
// are far inside that range). The translation unit is compiled
// without multiply-add contraction, on which its error-free transformations rely.
int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

}  // namespace corrmp
