// Tests of the CNMP update computed by a team of threads (cnmp/parallel_cnmp_step.hpp): it must
// give exactly the losses and weights of the one-thread update, whatever the number of workers,
// for widths that do and do not split evenly, with and without a context, and with a decoder of
// one layer.
#include "cnmp/parallel_cnmp_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>

#include "core/thread_budget.hpp"
#include "nn/gemm.hpp"

namespace corrmp {
namespace {

std::vector<NormalisedTrajectory> waves(const CnmpArchitecture& a, int count, int steps) {
  std::vector<NormalisedTrajectory> data;
  for (int d = 0; d < count; ++d) {
    NormalisedTrajectory t;
    t.xy.resize(steps, a.d_x + a.d_y);
    for (int i = 0; i < steps; ++i) {
      const float time = static_cast<float>(i) / static_cast<float>(steps - 1);
      t.xy(i, 0) = time;
      for (int k = 0; k < a.d_y; ++k) t.xy(i, 1 + k) = std::sin(time * (k + 2) + 0.3f * d);
    }
    t.context = nn::Mat<float>::Constant(1, a.d_context, 0.1f * static_cast<float>(d));
    data.push_back(t);
  }
  return data;
}

struct Trained {
  std::vector<float> losses;
  std::vector<Eigen::VectorXf> weights;
};

// `before(u)`, when given, runs before update u.
Trained train(const CnmpArchitecture& a, int workers, int updates, int64_t probe_every = 4000,
              int64_t probe_updates = 100, int64_t* team_updates = nullptr,
              TeamCores cores = TeamCores::own, const std::function<void(int)>& before = {}) {
  CnmpModel model(a, 3);
  const auto data = waves(a, 12, 40);
  CnmpTrainingParams params;
  params.batch_size = 5;
  params.max_observations = 6;
  params.max_targets = 9;
  BatchSampler sampler(data, a, params);
  ParallelCnmpStep updater(model.network(), 1e-3, workers, cores, probe_every, probe_updates);
  EXPECT_EQ(updater.workers(), workers);
  Rng rng(11);
  Trained out;
  for (int u = 0; u < updates; ++u) {
    if (before) before(u);
    sampler.draw(rng);
    out.losses.push_back(updater.step(sampler));
  }
  for (const auto& p : model.network().parameters()) out.weights.push_back(p.values());
  if (team_updates) *team_updates = updater.team_updates();
  return out;
}

void expect_identical(const Trained& a, const Trained& b) {
  ASSERT_EQ(a.losses.size(), b.losses.size());
  for (size_t i = 0; i < a.losses.size(); ++i)
    EXPECT_EQ(a.losses[i], b.losses[i]) << "update " << i;
  ASSERT_EQ(a.weights.size(), b.weights.size());
  for (size_t k = 0; k < a.weights.size(); ++k) {
    ASSERT_EQ(a.weights[k].size(), b.weights[k].size());
    EXPECT_EQ(0, std::memcmp(a.weights[k].data(), b.weights[k].data(),
                             sizeof(float) * static_cast<size_t>(a.weights[k].size())))
        << "parameter " << k;
  }
}

CnmpArchitecture architecture(int width, int d_context) {
  CnmpArchitecture a;
  a.d_x = 1;
  a.d_y = 3;
  a.d_context = d_context;
  a.width = width;
  return a;
}

// The team's bits equal one thread's only where float products run on the split-exact kernel.
#define SKIP_UNLESS_SPLIT_EXACT() \
  if (!nn::gemm_float_split_exact()) GTEST_SKIP() << "float products run on Eigen in this build"

TEST(ParallelCnmpStep, TwoWorkersGiveExactlyTheOneWorkerUpdates) {
  SKIP_UNLESS_SPLIT_EXACT();
  const CnmpArchitecture a = architecture(128, 2);
  const Trained one = train(a, 1, 40);
  const Trained two = train(a, 2, 40);
  expect_identical(one, two);
  EXPECT_LT(one.losses.back(), one.losses.front());  // it trains
}

TEST(ParallelCnmpStep, UnevenWidthsAndNoContextStayIdentical) {
  SKIP_UNLESS_SPLIT_EXACT();
  for (const auto& [width, decoder_layers] : {std::pair{37, 4}, {223, 4}, {37, 1}}) {
    CnmpArchitecture a = architecture(width, 0);
    a.decoder_layers = decoder_layers;  // 1: the first layer is the output layer
    const Trained one = train(a, 1, 15);
    for (int workers : {2, 3}) {
      SCOPED_TRACE(::testing::Message() << "width " << width << ", " << decoder_layers
                                        << " decoder layers, " << workers << " workers");
      expect_identical(one, train(a, workers, 15));
    }
  }
}

// Timing the team against one thread switches between them (2 of every 7 updates on each, then
// the faster): the same bits throughout.
TEST(ParallelCnmpStep, SwitchingBetweenTheTeamAndOneThreadKeepsTheBits) {
  SKIP_UNLESS_SPLIT_EXACT();
  const CnmpArchitecture a = architecture(96, 1);
  const Trained one = train(a, 1, 35);
  int64_t team_updates = 0;
  expect_identical(one, train(a, 2, 35, 7, 2, &team_updates));
  EXPECT_GE(team_updates, 10);  // the team's probes
  EXPECT_LE(team_updates, 25);  // not the other probes
}

// A team that borrows its second core runs alone while no thread waits, and on the team once
// one lends its core (the team being the faster here: no probes), with the same bits.
TEST(ParallelCnmpStep, ABorrowingTeamRunsOnlyOnALentCore) {
  SKIP_UNLESS_SPLIT_EXACT();
  const CnmpArchitecture a = architecture(64, 1);
  const Trained one = train(a, 1, 20);
  int64_t team_updates = -1;
  expect_identical(one, train(a, 2, 20, 5, 0, &team_updates, TeamCores::borrowed));
  EXPECT_EQ(team_updates, 0);
  {
    const SpareThread waiting;
    expect_identical(one, train(a, 2, 20, 5, 0, &team_updates, TeamCores::borrowed));
    EXPECT_EQ(team_updates, 20);
    EXPECT_TRUE(borrow_spare_thread());  // the team gave the core back when it was done
    return_spare_thread();
  }
  EXPECT_FALSE(borrow_spare_thread());
}

// When the lender stops waiting, the team gives its core back at the next update.
TEST(ParallelCnmpStep, ABorrowedCoreIsGivenBackWhenItsLenderStopsWaiting) {
  SKIP_UNLESS_SPLIT_EXACT();
  const CnmpArchitecture a = architecture(64, 1);
  const Trained one = train(a, 1, 20);
  auto waiting = std::make_unique<SpareThread>();
  int64_t team_updates = -1;
  const Trained lent = train(a, 2, 20, 1000, 0, &team_updates, TeamCores::borrowed, [&](int u) {
    if (u == 8) waiting.reset();
  });
  expect_identical(one, lent);
  EXPECT_EQ(team_updates, 8);
  EXPECT_FALSE(borrow_spare_thread());  // the count is back to none
}

// A batch whose loss is NaN (one NaN target) leaves the weights as the previous update left
// them, on one worker or two, and the next good batch updates them again.
TEST(ParallelCnmpStep, ANonFiniteLossLeavesTheWeightsUnchanged) {
  const CnmpArchitecture a = architecture(32, 1);
  for (int workers : {1, 2}) {
    SCOPED_TRACE(::testing::Message() << workers << " workers");
    CnmpModel model(a, 3);
    const auto good = waves(a, 4, 20);
    auto bad = good;
    for (auto& t : bad) t.xy.col(1).setConstant(std::numeric_limits<float>::quiet_NaN());
    CnmpTrainingParams params;
    params.batch_size = 4;
    BatchSampler good_batches(good, a, params), bad_batches(bad, a, params);
    ParallelCnmpStep updater(model.network(), 1e-3, workers);
    Rng rng(5);
    good_batches.draw(rng);
    ASSERT_TRUE(std::isfinite(updater.step(good_batches)));
    std::vector<Eigen::VectorXf> before;
    for (const auto& p : model.network().parameters()) before.push_back(p.values());
    bad_batches.draw(rng);
    EXPECT_FALSE(std::isfinite(updater.step(bad_batches)));
    const auto after = model.network().parameters();
    for (size_t k = 0; k < after.size(); ++k)
      EXPECT_TRUE((after[k].values().array() == before[k].array()).all()) << "parameter " << k;
    good_batches.draw(rng);
    ASSERT_TRUE(std::isfinite(updater.step(good_batches)));
    EXPECT_FALSE((after[0].values().array() == before[0].array()).all());
    // No gradient of the bad batch was left behind to reach this update.
    for (size_t k = 0; k < after.size(); ++k)
      EXPECT_TRUE(after[k].values().allFinite()) << "parameter " << k;
  }
}

}  // namespace
}  // namespace corrmp
