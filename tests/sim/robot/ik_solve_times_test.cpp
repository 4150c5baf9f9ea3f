// IkSolveTimes: the count, mean and median of the solves' wall times.
#include "sim/robot/ik_solve_times.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

TEST(IkSolveTimes, CountsAndAveragesTheSolvesWithTheirMedian) {
  IkSolveTimes times;
  EXPECT_EQ(times.solves(), 0);
  EXPECT_EQ(times.mean_seconds(), 0.0);
  EXPECT_EQ(times.median_seconds(), 0.0);
  for (double seconds : {10e-6, 20e-6, 30e-6, 40e-6, 1e-3}) times.add(seconds);
  EXPECT_EQ(times.solves(), 5);
  EXPECT_NEAR(times.mean_seconds(), 220e-6, 1e-12);
  EXPECT_NEAR(times.median_seconds(), 30e-6, 30e-6 * 0.006);
}

TEST(IkSolveTimes, TimesOutsideTheHistogramCountInItsEndBins) {
  IkSolveTimes times;
  times.add(0.0);
  times.add(1e-12);
  times.add(100.0);
  EXPECT_EQ(times.solves(), 3);
  EXPECT_LT(times.median_seconds(), 1.1e-8);
}

}  // namespace
}  // namespace corrmp
