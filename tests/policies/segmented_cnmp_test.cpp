// Tests of policies/segmented_cnmp.hpp: the segment networks train concurrently, and the trained
// networks are bit-identical whatever the thread budget.
#include "policies/segmented_cnmp.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <future>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/thread_budget.hpp"

namespace corrmp {

namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;

// Demonstrations with segments a, b, c: a sine per segment whose phase is the context.
std::vector<Demonstration> demonstrations(int count, uint64_t seed) {
  Rng rng(seed);
  std::vector<Demonstration> demos;
  for (int d = 0; d < count; ++d) {
    Demonstration demo;
    demo.scenario = std::to_string(d);
    int k = 0;
    for (const char* name : {"a", "b", "c"}) {
      const double phase = rng.uniform(-1.0, 1.0);
      SegmentTrajectory s;
      s.segment = name;
      s.x = Eigen::VectorXd::LinSpaced(12, 0.0, 1.0);
      s.y.resize(12, 2);
      for (int t = 0; t < 12; ++t) {
        s.y(t, 0) = std::sin(3.0 * s.x(t) + phase + k);
        s.y(t, 1) = phase * s.x(t);
      }
      s.context = Eigen::VectorXd::Constant(1, phase);
      demo.segments.push_back(s);
      ++k;
    }
    demos.push_back(demo);
  }
  return demos;
}

SegmentedCnmpParams small_params() {
  SegmentedCnmpParams params;
  params.segments = {{"a", false}, {"b", true}, {"c", true}};
  params.network.encoder_layers = 2;
  params.network.decoder_layers = 2;
  params.network.width = 16;
  params.training.updates = 2000;
  params.training.batch_size = 4;
  params.training.validate_every = 250;
  params.training.learning_rate = 1e-3;
  return params;
}

struct Trained {
  std::vector<PolicyTrainingSummary> summaries;
  std::vector<Eigen::MatrixXd> means;  // each segment's prediction for a fixed query
};

// Trains every network in one fit, or (`halves`) the context-free ones on a thread of their own
// while the others train, as the pipeline does around a context extractor.
Trained train_with_budget(int budget, bool halves = false) {
  const int saved = thread_budget();
  set_thread_budget(budget);
  SegmentedCnmp policy(small_params(), 11);
  const Rng rng(5);
  const auto train = demonstrations(12, 1);
  const auto validation = demonstrations(4, 2);
  Trained trained;
  if (halves) {
    auto context_free = std::async(std::launch::async, [&] {
      const InlineLoops one_thread;
      return policy.fit(train, validation, rng, Networks::without_context);
    });
    const auto with_context = policy.fit(train, validation, rng, Networks::with_context);
    trained.summaries = context_free.get();
    EXPECT_EQ(trained.summaries.size(), 1u);
    trained.summaries.insert(trained.summaries.end(), with_context.begin(), with_context.end());
  } else {
    trained.summaries = policy.fit(train, validation, rng);
  }
  set_thread_budget(saved);
  const Eigen::MatrixXd query = Eigen::VectorXd::LinSpaced(7, 0.0, 1.0);
  Eigen::MatrixXd observation(1, 3);
  observation << 0.0, 0.2, -0.1;
  for (const std::string& segment : policy.segments()) {
    trained.means.push_back(
        policy.generate(segment, observation, Eigen::VectorXd::Constant(1, 0.3), query).mean);
  }
  return trained;
}

TEST(SegmentedCnmp, TrainsBitIdenticalNetworksWhateverTheThreadBudgetOrPhases) {
  const Trained one = train_with_budget(1);
  const Trained two = train_with_budget(2);
  const Trained four = train_with_budget(4);
  const Trained halves = train_with_budget(2, true);
  ASSERT_EQ(one.summaries.size(), 3u);
  for (const Trained* other : {&two, &four, &halves}) {
    ASSERT_EQ(other->summaries.size(), 3u);
    for (size_t s = 0; s < 3; ++s) {
      EXPECT_EQ(other->summaries[s].segment, one.summaries[s].segment);
      EXPECT_EQ(other->summaries[s].parameters, one.summaries[s].parameters);
      EXPECT_EQ(other->summaries[s].report.best_update, one.summaries[s].report.best_update);
      EXPECT_EQ(other->summaries[s].report.final_loss, one.summaries[s].report.final_loss);
      EXPECT_EQ(other->summaries[s].report.best_validation.mean,
                one.summaries[s].report.best_validation.mean);
      EXPECT_EQ(other->means[s], one.means[s]) << "segment " << one.summaries[s].segment;
    }
  }
  // The summaries keep the configured order, and the segments learn different things.
  EXPECT_EQ(one.summaries[0].segment, "a");
  EXPECT_EQ(one.summaries[2].segment, "c");
  EXPECT_NE(one.means[1], one.means[2]);
}

TEST(SegmentedCnmp, AMissingSegmentFailsNamingIt) {
  SegmentedCnmpParams params = small_params();
  params.segments.push_back({"d", true});
  SegmentedCnmp policy(params, 11);
  const Rng rng(5);
  EXPECT_THAT([&] { policy.fit(demonstrations(3, 1), demonstrations(1, 2), rng); },
              ThrowsMessage<std::runtime_error>(StrEq("demonstration 0 has no segment 'd'")));
}

}  // namespace
}  // namespace corrmp
