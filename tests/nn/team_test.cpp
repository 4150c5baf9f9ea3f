// Tests of the team of threads of nn/team.hpp: shares that cover a range, a barrier that orders
// the members' writes, and an aborted barrier that releases its waiters.
#include "nn/team.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace corrmp::nn {
namespace {

TEST(Team, SharesAreContiguousAndCoverTheRange) {
  for (int size : {1, 2, 3, 4}) {
    for (Index n : {0, 1, 6, 37, 128, 223}) {
      Index next = 0;
      for (int member = 0; member < size; ++member) {
        const auto [first, count] = Team{member, size, nullptr}.share(n);
        EXPECT_EQ(first, next) << size << " members, n " << n;
        EXPECT_GE(count, 0);
        next = first + count;
      }
      EXPECT_EQ(next, n) << size << " members";
    }
  }
  EXPECT_EQ((Team{0, 2, nullptr}.share(223)), (std::pair<Index, Index>{0, 112}));
}

TEST(Team, TheBarrierOrdersEachRoundsWrites) {
  constexpr int kRounds = 2000;
  SpinBarrier barrier(2);
  std::vector<int> value(2, 0);
  int mismatches = 0;
  std::thread other([&] {
    const Team team{1, 2, &barrier};
    for (int round = 0; round < kRounds; ++round) {
      value[1] = round;
      team.sync();
      team.sync();  // member 0 reads between the two
    }
  });
  const Team team{0, 2, &barrier};
  for (int round = 0; round < kRounds; ++round) {
    value[0] = round;
    team.sync();
    if (value[1] != round) ++mismatches;
    team.sync();
  }
  other.join();
  EXPECT_EQ(mismatches, 0);
}

TEST(Team, AnAbortedBarrierReleasesItsWaiters) {
  SpinBarrier barrier(2);
  bool released = false;
  std::thread waiter([&] {
    try {
      barrier.wait();
    } catch (const TeamAborted&) {
      released = true;
    }
  });
  barrier.abort();
  waiter.join();
  EXPECT_TRUE(released);
  barrier.reset();
  std::thread partner([&] { barrier.wait(); });
  barrier.wait();  // usable again
  partner.join();
}

}  // namespace
}  // namespace corrmp::nn
