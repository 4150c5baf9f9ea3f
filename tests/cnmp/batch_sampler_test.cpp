// Tests of the CNMP training sampler (cnmp/batch_sampler.hpp): the distribution of what it draws
// is the training's, so a change in it (how many observations, which points, whether a target may
// also be observed) changes what the network learns even where every update is computed right.
#include "cnmp/batch_sampler.hpp"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace corrmp {
namespace {

// `count` trajectories of `steps` points whose y names them: y = 100 trajectory + step.
std::vector<NormalisedTrajectory> labelled(const CnmpArchitecture& a,
                                           const std::vector<int>& steps) {
  std::vector<NormalisedTrajectory> data;
  for (size_t d = 0; d < steps.size(); ++d) {
    NormalisedTrajectory t;
    t.xy.resize(steps[d], a.d_x + a.d_y);
    for (int i = 0; i < steps[d]; ++i) {
      t.xy(i, 0) = static_cast<float>(i) / static_cast<float>(steps[d] - 1);
      t.xy(i, 1) = static_cast<float>(100 * d + i);
    }
    t.context = nn::Mat<float>::Constant(1, a.d_context, static_cast<float>(d));
    data.push_back(t);
  }
  return data;
}

// The point a drawn row is: {trajectory, step}.
std::pair<int, int> point(float y) {
  const int label = static_cast<int>(y);
  return {label / 100, label % 100};
}

// The public CNMP code's protocol: one demonstration per update, uniformly; n observations
// uniform in 1..5; one target; all n + 1 points distinct, uniform over the time steps.
TEST(BatchSampler, ThePublicProtocolDrawsUniformlyAndNeverObservesItsTarget) {
  CnmpArchitecture a;
  a.d_context = 1;
  CnmpTrainingParams p;
  p.batch_size = 1;
  p.max_observations = 5;
  p.max_targets = 1;
  const int kSteps = 12, kDraws = 30000;
  const auto data = labelled(a, {kSteps, kSteps, kSteps});
  BatchSampler sampler(data, a, p);
  Rng rng(5);
  std::vector<double> observations_of(p.max_observations + 1), trajectory(3), target_step(kSteps),
      observed_step(kSteps);
  double observed_rows = 0;
  for (int draw = 0; draw < kDraws; ++draw) {
    sampler.draw(rng);
    const int n = sampler.counts().observations[0];
    ASSERT_TRUE(n >= 1 && n <= p.max_observations) << n;
    ASSERT_EQ(sampler.counts().targets[0], 1);
    ASSERT_EQ(sampler.target_rows(), 1);
    const auto [task, step] = point(sampler.target_y()(0, 0));
    ASSERT_EQ(sampler.contexts()(0, 0), static_cast<float>(task));
    std::set<int> seen{step};
    for (int i = 0; i < n; ++i) {
      const auto [obs_task, obs_step] = point(sampler.observations()(i, 1));
      ASSERT_EQ(obs_task, task) << "an observation from another demonstration";
      ASSERT_TRUE(seen.insert(obs_step).second) << "a point drawn twice (or the target observed)";
      observed_step[obs_step] += 1;
    }
    observations_of[n] += 1;
    trajectory[task] += 1;
    target_step[step] += 1;
    observed_rows += n;
  }
  for (int n = 1; n <= p.max_observations; ++n)
    EXPECT_NEAR(observations_of[n] / kDraws, 1.0 / p.max_observations, 0.012) << "n = " << n;
  EXPECT_NEAR(observed_rows / kDraws, 3.0, 0.03);  // the mean of 1..5
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(trajectory[d] / kDraws, 1.0 / 3, 0.012) << d;
  for (int s = 0; s < kSteps; ++s) {
    EXPECT_NEAR(target_step[s] / kDraws, 1.0 / kSteps, 0.008) << "target step " << s;
    EXPECT_NEAR(observed_step[s] / observed_rows, 1.0 / kSteps, 0.005) << "observed step " << s;
  }
}

// A batch shares n and m, capped per demonstration by its length (n <= T - 1, n + m <= T), each
// task's rows in task order.
TEST(BatchSampler, ABatchSharesItsCountsCappedByEachDemonstrationsLength) {
  CnmpArchitecture a;
  CnmpTrainingParams p;
  p.batch_size = 4;
  p.max_observations = 6;
  p.max_targets = 4;
  const auto data = labelled(a, {3, 40});
  BatchSampler sampler(data, a, p);
  Rng rng(9);
  for (int draw = 0; draw < 2000; ++draw) {
    sampler.draw(rng);
    int obs_row = 0, target_row = 0, n_long = -1, m_long = -1;
    for (int b = 0; b < p.batch_size; ++b) {
      const int n = sampler.counts().observations[b], m = sampler.counts().targets[b];
      const int task = point(sampler.observations()(obs_row, 1)).first;
      const int steps = task == 0 ? 3 : 40;
      ASSERT_TRUE(n >= 1 && n <= steps - 1 && m >= 1 && n + m <= steps) << n << " " << m;
      if (task == 1) {  // uncapped: the batch's draw itself
        if (n_long >= 0) {
          ASSERT_TRUE(n == n_long && m == m_long);
        }
        n_long = n;
        m_long = m;
      }
      std::set<int> seen;
      for (int i = 0; i < n; ++i, ++obs_row) {
        ASSERT_EQ(point(sampler.observations()(obs_row, 1)).first, task);
        seen.insert(point(sampler.observations()(obs_row, 1)).second);
      }
      for (int j = 0; j < m; ++j, ++target_row) {
        ASSERT_EQ(point(sampler.target_y()(target_row, 0)).first, task);
        seen.insert(point(sampler.target_y()(target_row, 0)).second);
      }
      ASSERT_EQ(static_cast<int>(seen.size()), n + m) << "points drawn twice";
    }
    ASSERT_EQ(obs_row, sampler.observation_rows());
    ASSERT_EQ(target_row, sampler.target_rows());
  }
}

}  // namespace
}  // namespace corrmp
