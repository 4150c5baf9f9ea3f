// The grid's pair search against all pairs on random polygons.
#include "envs/rope_knot/near_segment_pairs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include "core/seeds.hpp"

namespace corrmp {
namespace {

using Pairs = std::set<std::pair<int, int>>;

double box_gap(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1, const Eigen::Vector2d& b0,
               const Eigen::Vector2d& b1) {
  const Eigen::Vector2d lo = a0.cwiseMin(a1).cwiseMax(b0.cwiseMin(b1));
  const Eigen::Vector2d hi = a0.cwiseMax(a1).cwiseMin(b0.cwiseMax(b1));
  return (lo - hi).maxCoeff();  // > 0 along an axis where the boxes are apart
}

void expect_exactly_the_near_pairs(const std::vector<Eigen::Vector2d>& flat, double reach) {
  const int n = static_cast<int>(flat.size());
  Pairs visited;
  int calls = 0;
  for_each_near_segment_pair(flat, reach, [&](int i, int j) {
    ASSERT_LT(i, j);
    visited.insert({i, j});
    ++calls;
  });
  EXPECT_EQ(calls, static_cast<int>(visited.size())) << "a pair visited twice";
  Pairs expected;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (box_gap(flat[i], flat[(i + 1) % n], flat[j], flat[(j + 1) % n]) <= reach) {
        expected.insert({i, j});
      }
    }
  }
  EXPECT_EQ(visited, expected);
}

TEST(NearSegmentPairs, VisitsEveryPairWhoseGrownBoxesOverlapOnce) {
  Rng rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 3 + static_cast<int>(rng.uniform_int(0, 300));
    std::vector<Eigen::Vector2d> walk{{0, 0}};
    for (int k = 1; k < n; ++k) {
      walk.push_back(walk.back() + Eigen::Vector2d(rng.normal(), rng.normal()) * 0.1);
    }
    // A few long segments, as a rope closed far away has.
    if (trial % 2 == 0) walk.push_back({40.0, 40.0});
    for (double reach : {0.0, 0.01, 0.3, 5.0}) expect_exactly_the_near_pairs(walk, reach);
  }
}

TEST(NearSegmentPairs, DegenerateSizesVisitEveryPairThatIsNear) {
  const std::vector<Eigen::Vector2d> same(50, Eigen::Vector2d(0.3, -2.0));
  expect_exactly_the_near_pairs(same, 0.0);
  expect_exactly_the_near_pairs(same, 1.0);
  Rng rng(8);
  std::vector<Eigen::Vector2d> walk{{0, 0}};
  for (int k = 1; k < 60; ++k) walk.push_back(walk.back() + Eigen::Vector2d(rng.normal(), 0.1));
  expect_exactly_the_near_pairs(walk, std::numeric_limits<double>::infinity());
  std::vector<Eigen::Vector2d> huge;
  for (const auto& p : walk) huge.push_back(1e300 * p);
  expect_exactly_the_near_pairs(huge, 3.7e299);
  // Tiny segments on a line with long ones across the whole extent between them: the grid's
  // cells are small and each long box spans all of them.
  std::vector<Eigen::Vector2d> comb;
  for (int k = 0; k < 200; ++k) {
    comb.emplace_back(k * 1e-3, 0.0);
    if (k % 2 == 0) comb.emplace_back(1e9, k * 1e-9);
  }
  expect_exactly_the_near_pairs(comb, 0.0);
}

TEST(NearSegmentPairs, HandlesFlatAndTinyPolygons) {
  expect_exactly_the_near_pairs({{0, 0}, {1, 0}, {2, 0}, {3, 0}}, 0.1);
  expect_exactly_the_near_pairs({{0, 0}, {0, 1e-9}, {0, 2e-9}}, 0.0);
  expect_exactly_the_near_pairs({{0, 0}, {1, 1}}, 0.5);
}

}  // namespace
}  // namespace corrmp
