// bench_cnmp: CNMP training and prediction speed (Google Benchmark), one thread
// unless a benchmark says otherwise.
// "paper_b1" is the paper's setting (Section IV: encoder 3 x 128, decoder
// 4 x 128, Adam; d_x 1, d_y 3, context 1; batch 1, up to 5 observations, 1
// target): one full update = sampling + forward + backward + Adam step.
// items_per_second is updates per second; GFLOP/s counts the multiply-adds of
// the matrix products (2 flops each) of forward and backward passes with the
// decoder's first layer applied to every target row; it computes the
// representation's part once per task (cnmp/decoder_first_layer.hpp), so with
// several targets per task this is an effective rate.
#include <benchmark/benchmark.h>

#include <cmath>

#include "cnmp/batch_sampler.hpp"
#include "cnmp/cnmp_model.hpp"
#include "cnmp/parallel_cnmp_step.hpp"
#include "nn/adam.hpp"

namespace corrmp {
namespace {

CnmpArchitecture paper_architecture() {
  CnmpArchitecture a;
  a.d_x = 1;
  a.d_y = 3;
  a.d_context = 1;
  return a;
}

std::vector<NormalisedTrajectory> synthetic_trajectories(const CnmpArchitecture& a) {
  std::vector<NormalisedTrajectory> data;
  for (int d = 0; d < 100; ++d) {
    NormalisedTrajectory t;
    t.xy.resize(200, a.d_x + a.d_y);
    for (int i = 0; i < 200; ++i) {
      const float time = i / 199.0f;
      t.xy(i, 0) = time;
      for (int k = 0; k < a.d_y; ++k) t.xy(i, 1 + k) = std::sin(time * (k + 1) + d * 0.01f);
    }
    t.context = nn::Mat<float>::Constant(1, a.d_context, d / 100.0f);
    data.push_back(t);
  }
  return data;
}

// Flops of the matrix products of one update: per Linear layer (in -> out) over
// N rows, forward 2 N in out, weight gradient 2 N in out, input gradient
// 2 N in out (none for the encoder's first layer).
double update_flops(const CnmpArchitecture& a, double obs_rows, double target_rows) {
  const double w = a.width;
  double encoder = 4 * (a.d_x + a.d_y) * w + 6 * (a.encoder_layers - 1) * w * w;
  double decoder =
      6 * (w + a.d_context + a.d_x) * w + 6 * (a.decoder_layers - 2) * w * w + 6 * w * 2 * a.d_y;
  return obs_rows * encoder + target_rows * decoder;
}

void run_updates(benchmark::State& state, int batch_size, int max_observations, int max_targets) {
  const CnmpArchitecture a = paper_architecture();
  CnmpModel model(a, 1);
  const auto data = synthetic_trajectories(a);
  CnmpTrainingParams params;
  params.batch_size = batch_size;
  params.max_observations = max_observations;
  params.max_targets = max_targets;
  BatchSampler sampler(data, a, params);
  nn::Adam<float> adam(model.network().parameters(), nn::AdamOptions{1e-4});
  Rng rng(7);
  double obs_rows = 0, target_rows = 0;
  for (auto _ : state) {
    sampler.draw(rng);
    adam.zero_grad();
    benchmark::DoNotOptimize(sampler.step(model.network()));
    adam.step();
    obs_rows += sampler.observation_rows();
    target_rows += sampler.target_rows();
  }
  const double updates = static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations());
  state.counters["GFLOP/s"] =
      benchmark::Counter(update_flops(a, obs_rows / updates, target_rows / updates) * updates / 1e9,
                         benchmark::Counter::kIsRate);
  state.counters["params"] = static_cast<double>(model.network().parameter_count());
}

void BM_update_paper_b1(benchmark::State& state) { run_updates(state, 1, 5, 1); }
void BM_update_b32(benchmark::State& state) { run_updates(state, 32, 5, 1); }
void BM_update_b32_targets10(benchmark::State& state) { run_updates(state, 32, 5, 10); }
// The default configs' step (configs/common/cnmp.yaml): 8 demonstrations, up to 5
// observations and 10 targets each.
void BM_update_defaults_b8_targets10(benchmark::State& state) { run_updates(state, 8, 5, 10); }

// The default step (8 demonstrations, up to 10 targets) at width state.range(0) (223: the
// corridor's monolithic baseline) on state.range(1) threads (cnmp/parallel_cnmp_step.hpp).
void BM_update_parallel(benchmark::State& state) {
  CnmpArchitecture a = paper_architecture();
  a.width = static_cast<int>(state.range(0));
  CnmpModel model(a, 1);
  const auto data = synthetic_trajectories(a);
  CnmpTrainingParams params;
  params.batch_size = 8;
  params.max_targets = 10;
  BatchSampler sampler(data, a, params);
  // Always the team (no timing against one thread), to measure it.
  ParallelCnmpStep updater(model.network(), 1e-4, static_cast<int>(state.range(1)), TeamCores::own,
                           1, 0);
  Rng rng(7);
  for (auto _ : state) {
    sampler.draw(rng);
    benchmark::DoNotOptimize(updater.step(sampler));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_predict_200_points(benchmark::State& state) {
  const CnmpArchitecture a = paper_architecture();
  CnmpModel model(a, 1);
  Eigen::MatrixXd start(1, a.d_x + a.d_y);
  start << 0.0, 0.1, 0.2, 0.3;
  const Eigen::VectorXd context = Eigen::VectorXd::Constant(1, 0.5);
  Eigen::MatrixXd query(200, 1);
  for (int i = 0; i < 200; ++i) query(i, 0) = i / 199.0;
  for (auto _ : state) benchmark::DoNotOptimize(model.predict(start, context, query));
  state.SetItemsProcessed(state.iterations());
  state.counters["GFLOP/s"] = benchmark::Counter(
      (2.0 * (a.d_x + a.d_y) * a.width + 2.0 * 2 * a.width * a.width +
       200 * (2.0 * (a.width + 2) * a.width + 2.0 * 2 * a.width * a.width + 2.0 * a.width * 6)) *
          static_cast<double>(state.iterations()) / 1e9,
      benchmark::Counter::kIsRate);
}

BENCHMARK(BM_update_paper_b1);
BENCHMARK(BM_update_b32);
BENCHMARK(BM_update_b32_targets10);
BENCHMARK(BM_update_defaults_b8_targets10);
BENCHMARK(BM_update_parallel)
    ->Args({128, 1})
    ->Args({128, 2})
    ->Args({223, 1})
    ->Args({223, 2})
    ->UseRealTime();
BENCHMARK(BM_predict_200_points)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace corrmp

BENCHMARK_MAIN();
