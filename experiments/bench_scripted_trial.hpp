// Times whole scripted half-hitch trials of a rope scene (floating or on the
// arms): counters real_time_factor (simulated seconds per second), simulated_s
// (one trial) and knots (the share of trials that tied one).
#pragma once

#include <benchmark/benchmark.h>

#include "envs/rope_knot/rope_knot_scene.hpp"
#include "envs/rope_knot/rope_knot_script.hpp"

namespace corrmp {

inline void time_scripted_trials(benchmark::State& state, RopeKnotScene& scene) {
  double simulated = 0;
  int knots = 0;
  for (auto _ : state) {
    knots += scripted_trial(scene, {}, true).knot;
    simulated += scene.time();
  }
  state.counters["real_time_factor"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  state.counters["simulated_s"] = scene.time();
  state.counters["knots"] = benchmark::Counter(knots, benchmark::Counter::kAvgIterations);
}

}  // namespace corrmp
