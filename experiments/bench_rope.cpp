// bench_rope: speed of the soft-body rope simulation of the knotting task
// (paper, Section IV-C, "Knotting with the real robot", reproduced in
// simulation). The counter real_time_factor is simulated seconds per wall-clock
// second (kIsRate over simulated time).
//   BM_RopeStep: one tick (1/600 s, one Bullet step plus the self-contact pass)
//     of a 96-node rope draped over the bar, swinging.
//   BM_ScriptedTrial: a whole scripted half-hitch trial (reset, settle, pre-MP,
//     correction, post-MP, knot check) of the nominal scenario.
//   BM_KnotDeterminant/N: the knot determinant of an N-vertex (2, 5) torus knot
//     polygon (all 16 candidate projections).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "envs/rope_knot/knot_check.hpp"

#include "bench_scripted_trial.hpp"
#include "envs/rope_knot/rope_knot_scene.hpp"
#include "envs/rope_knot/rope_knot_script.hpp"
#include "sim/soft/rope.hpp"
#include "sim/soft/soft_world.hpp"

namespace corrmp {
namespace {

void BM_RopeStep(benchmark::State& state) {
  const RopeKnotParams params;
  SoftWorld world(params.world);
  world.add_bar("bar", {0, 0, 1}, params.bar_radius, params.bar_length, params.bar_friction);
  Rope rope(world, params.rope,
            straight_rope(params.rope, {-0.4, 0.0, 1.02}, Eigen::Vector3d(1.0, 0.1, 0.0)));
  for (auto _ : state) world.step();
  state.counters["real_time_factor"] =
      benchmark::Counter(world.time(), benchmark::Counter::kIsRate);
  state.counters["nodes"] = rope.node_count();
}
BENCHMARK(BM_RopeStep);

void BM_ScriptedTrial(benchmark::State& state) {
  RopeKnotScene scene(RopeKnotParams{});
  time_scripted_trials(state, scene);
}
BENCHMARK(BM_ScriptedTrial)->Unit(benchmark::kMillisecond);

void BM_KnotDeterminant(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  std::vector<Eigen::Vector3d> polygon;
  for (int k = 0; k < count; ++k) {
    const double t = 2.0 * M_PI * k / count, r = 2.0 + std::cos(5.0 * t);
    polygon.emplace_back(r * std::cos(2.0 * t), r * std::sin(2.0 * t), std::sin(5.0 * t));
  }
  int determinant = 0;
  for (auto _ : state) determinant = knot_determinant(polygon);
  state.counters["determinant"] = determinant;
}
BENCHMARK(BM_KnotDeterminant)->Arg(100)->Arg(1000)->Arg(8000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace corrmp

BENCHMARK_MAIN();
