// Tests of the CNMP update computed by a team of threads (cnmp/parallel_cnmp_step.hpp): it must
// give exactly the losses and weights of the one-thread update, whatever the number of workers,
// for widths that do and do not split evenly and with and without a context.
#include "cnmp/parallel_cnmp_step.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

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

Trained train(const CnmpArchitecture& a, int workers, int updates) {
  CnmpModel model(a, 3);
  const auto data = waves(a, 12, 40);
  CnmpTrainingParams params;
  params.batch_size = 5;
  params.max_observations = 6;
  params.max_targets = 9;
  BatchSampler sampler(data, a, params);
  ParallelCnmpStep updater(model.network(), 1e-3, workers);
  EXPECT_EQ(updater.workers(), workers);
  Rng rng(11);
  Trained out;
  for (int u = 0; u < updates; ++u) {
    sampler.draw(rng);
    out.losses.push_back(updater.step(sampler));
  }
  for (const auto& p : model.network().parameters()) out.weights.push_back(p.values());
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

TEST(ParallelCnmpStep, TwoWorkersGiveExactlyTheOneWorkerUpdates) {
  const CnmpArchitecture a = architecture(128, 2);
  const Trained one = train(a, 1, 40);
  const Trained two = train(a, 2, 40);
  expect_identical(one, two);
  EXPECT_LT(one.losses.back(), one.losses.front());  // it trains
}

TEST(ParallelCnmpStep, UnevenWidthsAndNoContextStayIdentical) {
  for (int width : {37, 223}) {
    const CnmpArchitecture a = architecture(width, 0);
    const Trained one = train(a, 1, 15);
    for (int workers : {2, 3}) {
      SCOPED_TRACE(testing::Message() << "width " << width << ", " << workers << " workers");
      expect_identical(one, train(a, workers, 15));
    }
  }
}

TEST(ParallelCnmpStep, ANonFiniteLossLeavesTheWeightsUnchanged) {
  const CnmpArchitecture a = architecture(32, 1);
  for (int workers : {1, 2}) {
    CnmpModel model(a, 3);
    auto data = waves(a, 4, 20);
    for (auto& t : data) t.xy(5, 1) = std::numeric_limits<float>::quiet_NaN();
    CnmpTrainingParams params;
    params.batch_size = 4;
    params.max_observations = 19;
    params.max_targets = 19;
    BatchSampler sampler(data, a, params);
    ParallelCnmpStep updater(model.network(), 1e-3, workers);
    std::vector<Eigen::VectorXf> before;
    for (const auto& p : model.network().parameters()) before.push_back(p.values());
    Rng rng(5);
    float loss = 0.0f;
    for (int u = 0; u < 20 && std::isfinite(loss); ++u) {
      sampler.draw(rng);
      loss = updater.step(sampler);
    }
    ASSERT_FALSE(std::isfinite(loss)) << workers << " workers";
    const auto params_after = model.network().parameters();
    // Only the updates before the non-finite one changed the weights; that one did not (a NaN
    // would have spread into them).
    for (size_t k = 0; k < params_after.size(); ++k)
      EXPECT_TRUE(params_after[k].values().allFinite()) << workers << " workers, parameter " << k;
  }
}

}  // namespace
}  // namespace corrmp
