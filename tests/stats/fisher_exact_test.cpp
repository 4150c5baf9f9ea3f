// Tests of Fisher's exact test against R's fisher.test two-sided p-values
// (and exact fractions where they are short).
#include "stats/fisher_exact.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace corrmp {
namespace {

TEST(FisherExact, MatchesRsTwoSidedPValues) {
  // fisher.test(matrix(c(3, 1, 1, 3), 2)): 0.4857 (= 34 / 70).
  EXPECT_NEAR(fisher_exact_two_sided(3, 1, 1, 3), 34.0 / 70.0, 1e-14);
  // fisher.test(matrix(c(1, 11, 9, 3), 2)): 0.002759.
  EXPECT_NEAR(fisher_exact_two_sided(1, 9, 11, 3), 0.002759456185220083, 1e-15);
  // 10 of 10 against 0 of 10: 2 / choose(20, 10).
  EXPECT_NEAR(fisher_exact_two_sided(10, 0, 0, 10), 2.0 / 184756.0, 1e-18);
  EXPECT_NEAR(fisher_exact_two_sided(7, 3, 2, 8), 0.06977851869492735, 1e-15);
}

TEST(FisherExact, IsSymmetricInRowsAndColumns) {
  const double p = fisher_exact_two_sided(7, 3, 2, 8);
  EXPECT_NEAR(fisher_exact_two_sided(2, 8, 7, 3), p, 1e-15);  // rows swapped
  EXPECT_NEAR(fisher_exact_two_sided(7, 2, 3, 8), p, 1e-15);  // transposed
}

TEST(FisherExact, IsOneWithoutEvidenceOfADifference) {
  EXPECT_DOUBLE_EQ(fisher_exact_two_sided(5, 0, 5, 0), 1.0);    // every trial succeeded
  EXPECT_DOUBLE_EQ(fisher_exact_two_sided(0, 0, 4, 2), 1.0);    // a group without trials
  EXPECT_NEAR(fisher_exact_two_sided(2, 2, 2, 2), 1.0, 1e-14);  // the most probable table
}

TEST(FisherExact, RefusesNegativeCounts) {
  EXPECT_THROW(fisher_exact_two_sided(-1, 2, 3, 4), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
