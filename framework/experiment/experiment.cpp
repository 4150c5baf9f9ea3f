// Loading and validating an experiment config into components.
#include "experiment/experiment.hpp"

#include <fmt/format.h>

#include "core/config/config_loader.hpp"
#include "core/parameter_error.hpp"
#include "core/seeds.hpp"
#include "experiment/component_checks.hpp"

namespace corrmp {

namespace {

void check_name(const ConfigNode& root, const std::string& name) {
  if (!is_safe_file_name(name)) {
    const ConfigNode* node = root.find("experiment")->find("name");
    throw ConfigError(node->where(), "experiment.name",
                      fmt::format("'{}' is not a valid name: use up to 128 letters, digits, '_', "
                                  "'-', '.', not starting with '.'",
                                  name));
  }
}

}  // namespace

Experiment load_experiment(const std::string& config_path,
                           const std::vector<std::string>& overrides,
                           const Registries& registries) {
  Experiment experiment;
  experiment.config_path = config_path;
  experiment.root = std::make_unique<ConfigNode>(load_config(config_path, overrides));
  ConfigReader::read(*experiment.root, "", experiment.config);
  check_name(*experiment.root, experiment.config.experiment.name);

  experiment.seeds = SeedTree(experiment.config.seed);
  const ExperimentConfig& config = experiment.config;
  if (config.environment) {
    experiment.environment = registries.environments.create(*config.environment, experiment.seeds);
  }
  if (config.demonstrations) {
    experiment.demonstrations =
        registries.demonstrations.create(*config.demonstrations, experiment.seeds);
    if (experiment.demonstrations->needs_environment() && !experiment.environment) {
      const ConfigNode* type = config.demonstrations->node->find("type");
      throw ConfigError(type->where(), "demonstrations.type",
                        fmt::format("'{}' demonstrates in an environment: add an environment "
                                    "section",
                                    config.demonstrations->type));
    }
  }
  if (config.context) {
    experiment.context_extractor = registries.contexts.create(*config.context, experiment.seeds);
  }
  if (config.policy) {
    experiment.policy = registries.policies.create(*config.policy, experiment.seeds);
  }

  check_components(experiment);

  experiment.resolved_yaml = experiment.root->to_yaml_string();
  experiment.config_hash = fmt::format("{:016x}", fnv1a64(experiment.resolved_yaml));
  return experiment;
}

}  // namespace corrmp
