// Tests of filling an expert's demonstration split: failed demonstrations are
// dropped, the sets fill in order, and running out of tries says how many
// succeeded.
#include "data/expert_collection.hpp"

#include <gtest/gtest.h>

namespace corrmp {
namespace {

Demonstration named(int i) {
  Demonstration demo;
  demo.scenario = std::to_string(i);
  return demo;
}

TEST(ExpertCollection, DropsFailuresAndFillsTrainThenValidation) {
  int calls = 0;
  const DemonstrationSplit split = collect_expert_demonstrations({2, 1, 10, "test"}, [&] {
    const int i = calls++;
    if (i % 2 == 1) throw std::runtime_error("dropped");
    return named(i);
  });
  ASSERT_EQ(split.train.size(), 2u);
  ASSERT_EQ(split.validation.size(), 1u);
  EXPECT_EQ(split.train[0].scenario, "0");
  EXPECT_EQ(split.train[1].scenario, "2");
  EXPECT_EQ(split.validation[0].scenario, "4");
  EXPECT_EQ(calls, 5);
}

TEST(ExpertCollection, RunningOutOfTriesSaysHowManySucceeded) {
  int calls = 0;
  try {
    collect_expert_demonstrations({3, 0, 4, "the expert"}, [&]() -> Demonstration {
      if (calls++ < 3) throw std::runtime_error("dropped");
      return named(calls);
    });
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "the expert succeeded on only 1 of the 4 scenarios tried (3 wanted)");
  }
  EXPECT_EQ(calls, 4);
}

}  // namespace
}  // namespace corrmp
