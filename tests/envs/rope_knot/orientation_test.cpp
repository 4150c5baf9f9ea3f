// The exact orientation predicate on points where rounded arithmetic (with or without
// multiply-add contraction) gets the sign wrong.
#include "envs/rope_knot/orientation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corrmp {
namespace {

// c a few units in the last place off the line y = x through a and b: the sign is that of
// c.y - c.x, which the rounded determinant misses for many of these points.
TEST(Orientation, ExactForPointsWithinAnUlpOfTheLine) {
  const Eigen::Vector2d a(12.0, 12.0), b(24.0, 24.0);
  const double ulp = std::ldexp(1.0, -53);
  for (int i = 0; i < 32; ++i) {
    for (int j = 0; j < 32; ++j) {
      const Eigen::Vector2d c(0.5 + i * ulp, 0.5 + j * ulp);
      const int expected = j > i ? 1 : (j < i ? -1 : 0);
      EXPECT_EQ(orientation(a, b, c), expected) << i << ", " << j;
      EXPECT_EQ(orientation(b, a, c), -expected) << i << ", " << j;
      EXPECT_EQ(orientation(c, a, b), expected) << i << ", " << j;
    }
  }
}

TEST(Orientation, CollinearPointsAreZeroAndTurnsHaveTheirSign) {
  EXPECT_EQ(orientation({0.1, 0.3}, {0.2, 0.6}, {0.4, 1.2}), 0);
  EXPECT_EQ(orientation({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(orientation({0, 0}, {0, 1}, {1, 0}), -1);
  EXPECT_EQ(orientation({1e-3, 2e-3}, {1e-3, 2e-3}, {5, 7}), 0);
}

}  // namespace
}  // namespace corrmp
