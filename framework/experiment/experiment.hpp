// A loaded experiment: the resolved config tree, its typed top level and the
// components built from the registries. Loading validates everything (each
// component reads its parameters strictly), so a malformed config fails here,
// before anything is written. docs/architecture.md, "Configs".
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/config/config_node.hpp"
#include "core/seeds.hpp"
#include "experiment/experiment_config.hpp"
#include "experiment/registries.hpp"

namespace corrmp {

struct Experiment {
  std::string config_path;
  std::unique_ptr<ConfigNode> root;  // owns the nodes ComponentSpecs point into
  ExperimentConfig config;
  SeedTree seeds{0};  // the run's seed streams, from config.seed
  std::unique_ptr<Environment> environment;
  std::unique_ptr<DemonstrationSource> demonstrations;
  std::unique_ptr<ContextExtractor> context_extractor;
  std::unique_ptr<Policy> policy;

  std::string resolved_yaml;  // every value in force, defaults included
  std::string config_hash;    // of resolved_yaml
};

// Throws ConfigError for any problem in the config or the overrides.
Experiment load_experiment(const std::string& config_path,
                           const std::vector<std::string>& overrides, const Registries& registries);

}  // namespace corrmp
