// Tests of filling an expert's demonstration split: failed demonstrations are
// dropped, the sets fill with the successes in attempt order, running out of
// tries says how many succeeded, and the split is the same whatever the number
// of threads.
#include "data/expert_collection.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "core/thread_budget.hpp"

namespace corrmp {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;

// Restores the thread budget after each test.
class ExpertCollectionTest : public ::testing::Test {
 protected:
  void SetUp() override { saved_ = thread_budget(); }
  void TearDown() override { set_thread_budget(saved_); }

 private:
  int saved_ = 1;
};

// An attempt that draws one number: it fails when the number is divisible by
// `fail_every`, else its demonstration is named by the number. It takes a
// little time, so parallel attempts overlap.
ExpertAttempt numbered(uint64_t fail_every) {
  return [fail_every](Rng& rng, int) {
    const uint64_t value = rng() % 1000;
    std::this_thread::sleep_for(std::chrono::microseconds(100 * (value % 4)));
    if (value % fail_every == 0) throw std::runtime_error("dropped " + std::to_string(value));
    Demonstration demo;
    demo.scenario = std::to_string(value);
    return demo;
  };
}

// The names a single thread trying attempt after attempt collects.
std::vector<std::string> expected_names(uint64_t seed, uint64_t fail_every, int wanted) {
  const uint64_t base = Rng(seed)();
  std::vector<std::string> names;
  for (int index = 0; static_cast<int>(names.size()) < wanted; ++index) {
    Rng rng = expert_attempt_stream(base, index);
    const uint64_t value = rng() % 1000;
    if (value % fail_every != 0) names.push_back(std::to_string(value));
  }
  return names;
}

std::vector<std::string> names_of(const DemonstrationSplit& split) {
  std::vector<std::string> names;
  for (const auto* set : {&split.train, &split.validation}) {
    for (const auto& demo : *set) names.push_back(demo.scenario);
  }
  return names;
}

TEST_F(ExpertCollectionTest, FillsTrainThenValidationWithTheSuccessesInAttemptOrder) {
  const std::vector<std::string> expected = expected_names(3, 3, 30);
  for (int budget : {1, 2, 4}) {
    set_thread_budget(budget);
    Rng rng(3);
    const DemonstrationSplit split =
        collect_expert_demonstrations({20, 10, 200, "test"}, rng, budget, numbered(3));
    ASSERT_EQ(split.train.size(), 20u);
    ASSERT_EQ(split.validation.size(), 10u);
    EXPECT_EQ(names_of(split), expected) << "budget " << budget;
  }
}

TEST_F(ExpertCollectionTest, DrawsOnceFromTheExpertsStream) {
  Rng rng(3);
  collect_expert_demonstrations({2, 1, 20, "test"}, rng, 1, numbered(3));
  Rng reference(3);
  reference();
  EXPECT_EQ(rng(), reference());
}

TEST_F(ExpertCollectionTest, RunningOutOfTriesSaysHowManySucceeded) {
  // With attempts failing for every even number, about half of 6 succeed.
  const uint64_t base = Rng(4)();
  int successes = 0;
  for (int index = 0; index < 6; ++index) {
    Rng rng = expert_attempt_stream(base, index);
    successes += (rng() % 1000) % 2 != 0;
  }
  ASSERT_LT(successes, 6);
  for (int budget : {1, 2}) {
    set_thread_budget(budget);
    Rng rng(4);
    EXPECT_THAT(
        [&] {
          collect_expert_demonstrations({6, 0, 6, "the expert"}, rng, 2, numbered(2));
        },
        ThrowsMessage<std::runtime_error>(StrEq("the expert succeeded on only " +
                                                std::to_string(successes) +
                                                " of the 6 scenarios tried (6 wanted)")));
  }
}

TEST_F(ExpertCollectionTest, RethrowsTheFirstErrorThatIsNoDroppedDemonstration) {
  // Attempts fail fatally on a multiple of 7; every other attempt succeeds.
  const auto attempt = [](Rng& rng, int) -> Demonstration {
    const uint64_t value = rng() % 1000;
    if (value % 7 == 0) throw std::logic_error("fatal " + std::to_string(value));
    return Demonstration{};
  };
  const uint64_t base = Rng(8)();
  std::string first_fatal;
  for (int index = 0; first_fatal.empty(); ++index) {
    Rng rng = expert_attempt_stream(base, index);
    const uint64_t value = rng() % 1000;
    if (value % 7 == 0) first_fatal = "fatal " + std::to_string(value);
  }
  for (int budget : {1, 2, 4}) {
    set_thread_budget(budget);
    Rng rng(8);
    EXPECT_THAT(
        [&] {
          collect_expert_demonstrations({500, 0, 1000, "test"}, rng, budget, attempt);
        },
        ThrowsMessage<std::logic_error>(StrEq(first_fatal)))
        << "budget " << budget;
  }
}

TEST_F(ExpertCollectionTest, EachWorkerRunsOneAttemptAtATime) {
  set_thread_budget(4);
  std::vector<std::atomic<int>> busy(2);
  std::atomic<int> clashes{0}, out_of_range{0};
  Rng rng(1);
  const ExpertAttempt inner = numbered(1000);
  collect_expert_demonstrations({30, 0, 60, "test"}, rng, 2, [&](Rng& attempt_rng, int worker) {
    if (worker < 0 || worker >= 2) {
      ++out_of_range;
      return inner(attempt_rng, worker);
    }
    if (busy[static_cast<size_t>(worker)]++ != 0) ++clashes;
    Demonstration demo = inner(attempt_rng, worker);
    --busy[static_cast<size_t>(worker)];
    return demo;
  });
  EXPECT_EQ(out_of_range.load(), 0);
  EXPECT_EQ(clashes.load(), 0);
}

}  // namespace
}  // namespace corrmp
