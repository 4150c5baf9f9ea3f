#include "envs/rope_knot/orientation.hpp"

#include <cmath>

namespace corrmp {
namespace {

// Error-free transformations: a * b = product + error and a + b = sum + error exactly.
// They need round-to-nearest and no contraction of a * b into a following addition.
void two_product(double a, double b, double& product, double& error) {
  product = a * b;
  error = std::fma(a, b, -product);
}

void two_sum(double a, double b, double& sum, double& error) {
  sum = a + b;
  const double b_virtual = sum - a;
  const double a_virtual = sum - b_virtual;
  error = (a - a_virtual) + (b - b_virtual);
}

// Sign of the exact sum of `count` doubles: grows a non-overlapping expansion term by term
// (each step adds one double exactly); its largest non-zero component carries the sign.
int sign_of_exact_sum(const double* terms, int count) {
  double expansion[12];
  int size = 0;
  for (int k = 0; k < count; ++k) {
    double carry = terms[k];
    for (int i = 0; i < size; ++i) two_sum(carry, expansion[i], carry, expansion[i]);
    expansion[size++] = carry;
  }
  for (int i = size - 1; i >= 0; --i) {
    if (expansion[i] > 0.0) return 1;
    if (expansion[i] < 0.0) return -1;
  }
  return 0;
}

int sign(double value) { return value > 0.0 ? 1 : (value < 0.0 ? -1 : 0); }

}  // namespace

int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double left = (b.x() - a.x()) * (c.y() - a.y());
  const double right = (b.y() - a.y()) * (c.x() - a.x());
  const double determinant = left - right;
  // Shewchuk's bound (3 + 16 eps) eps on the error of this evaluation without contraction.
  constexpr double kRelativeError = 3.3306690738754716e-16;
  if (std::abs(determinant) > kRelativeError * (std::abs(left) + std::abs(right))) {
    return sign(determinant);
  }
  // | b - a, c - a | = bx cy - bx ay - ax cy - by cx + by ax + ay cx, each product split
  // into its rounded value and its exact error.
  const double factors[6][2] = {{b.x(), c.y()},  {-b.x(), a.y()}, {-a.x(), c.y()},
                                {-b.y(), c.x()}, {b.y(), a.x()},  {a.y(), c.x()}};
  double terms[12];
  for (int k = 0; k < 6; ++k)
    two_product(factors[k][0], factors[k][1], terms[2 * k], terms[2 * k + 1]);
  return sign_of_exact_sum(terms, 12);
}

}  // namespace corrmp
