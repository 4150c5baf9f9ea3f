// The top level of an experiment config: docs/architecture.md, "Configs".
// Component sections (demonstrations, policy, ...) carry a `type:` naming a
// registry entry; their parameters are read by that entry.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/config/config_reader.hpp"

namespace corrmp {

struct ExperimentInfo {
  std::string name;
  std::string description;

  template <class Fields>
  void describe(Fields& f) {
    f("name", name, "experiment name; runs go to <out>/<name>/<run id>/", required());
    f("description", description, "free text shown in --print-config");
  }
};

struct EvaluationConfig {
  int trials = 25;
  uint64_t seed = 1;

  template <class Fields>
  void describe(Fields& f) {
    f("trials", trials, "number of evaluation trials", in_range(1, 100000));
    f("seed", seed,
      "seed of the evaluation scenarios, a stream disjoint from everything used in training");
  }
};

struct OutputConfig {
  bool write_predictions = true;

  template <class Fields>
  void describe(Fields& f) {
    f("write_predictions", write_predictions,
      "write predicted and demonstrated trajectories as CSV into the run directory");
  }
};

struct ExperimentConfig {
  ExperimentInfo experiment;
  uint64_t seed = 0;
  std::optional<ComponentSpec> environment;
  std::optional<ComponentSpec> demonstrations;
  std::optional<ComponentSpec> context;
  std::optional<ComponentSpec> policy;
  EvaluationConfig evaluation;
  OutputConfig output;

  template <class Fields>
  void describe(Fields& f) {
    f("experiment", experiment, "what this experiment is", required());
    f("seed", seed, "root seed: every component draws from a stream derived from it and its name");
    f("environment", environment, "the simulated task (type: a registered environment)");
    f("demonstrations", demonstrations,
      "where demonstrations come from (type: a registered demonstration source)");
    f("context", context, "context extractor (type: a registered extractor)");
    f("policy", policy, "the policy learned from the demonstrations (type: a registered policy)");
    f("evaluation", evaluation, "how the learned policy is evaluated");
    f("output", output, "what is written into the run directory");
  }
};

}  // namespace corrmp
