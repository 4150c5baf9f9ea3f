// Cross-component checks at load (component_checks.hpp).
#include "experiment/component_checks.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/memory_need.hpp"
#include "core/parameter_error.hpp"

namespace corrmp {

namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string listed(const std::vector<std::string>& names) {
  return names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "));
}

struct Located {
  SourceLocation where;
  std::string path;
};

// The first scalar under `node` whose text is `text`, with its key path.
bool find_scalar(const ConfigNode& node, const std::string& path, const std::string& text,
                 Located& found) {
  if (node.is_scalar()) {
    if (node.text() != text || node.where().file == "<default>") return false;
    found = {node.where(), path};
    return true;
  }
  if (node.is_sequence()) {
    int index = 0;
    for (const auto& item : node.items()) {
      if (find_scalar(item, fmt::format("{}[{}]", path, index++), text, found)) return true;
    }
  }
  if (node.is_map()) {
    for (const auto& entry : node.entries()) {
      if (find_scalar(entry.value, path + "." + entry.key, text, found)) return true;
    }
  }
  return false;
}

// Where a component section states `value`; its type line when only a
// default states it.
Located locate(const ComponentSpec& spec, const std::string& value) {
  Located found;
  if (find_scalar(*spec.node, spec.path, value, found)) return found;
  return {spec.node->find("type")->where(), spec.path + ".type"};
}

// Where a component section states `key`; its type line when it does not.
Located locate_key(const ComponentSpec& spec, const std::string& key) {
  const ConfigNode* node = spec.node->find(key);
  if (node != nullptr && node->where().file != "<default>")
    return {node->where(), spec.path + "." + key};
  return {spec.node->find("type")->where(), spec.path + ".type"};
}

void check_policy_data(const Experiment& e) {
  const std::vector<std::string> available = e.demonstrations->segments();
  if (available.empty()) return;  // only the data tells
  for (const auto& segment : e.policy->data_segments()) {
    if (contains(available, segment)) continue;
    const Located at = locate(*e.config.policy, segment);
    throw ConfigError(
        at.where, at.path,
        fmt::format("segment '{}' is not in the demonstrations of '{}' (they hold: {})", segment,
                    e.config.demonstrations->type, listed(available)));
  }
}

void check_policy_contexts(const Experiment& e) {
  if (e.demonstrations && e.demonstrations->provides_contexts()) return;
  const std::vector<std::string> given =
      e.context_extractor ? e.context_extractor->segments() : std::vector<std::string>{};
  for (const auto& segment : e.policy->context_segments()) {
    if (contains(given, segment)) continue;
    const Located at = locate(*e.config.policy, segment);
    const std::string source =
        e.context_extractor
            ? fmt::format("the context extractor '{}' gives none for it (it gives: {})",
                          e.config.context->type, listed(given))
            : std::string("there is no context section");
    throw ConfigError(at.where, at.path,
                      fmt::format("segment '{}' is conditioned on a context, but {}; add it to "
                                  "the context or set use_context: false",
                                  segment, source));
  }
}

void check_extractor_segments(const Experiment& e) {
  if (!e.demonstrations) return;
  const std::vector<std::string> available = e.demonstrations->segments();
  if (available.empty()) return;
  for (const auto& segment : e.context_extractor->segments()) {
    if (contains(available, segment)) continue;
    const Located at = locate(*e.config.context, segment);
    throw ConfigError(
        at.where, at.path,
        fmt::format("segment '{}' is not in the demonstrations of '{}' (they hold: {})", segment,
                    e.config.demonstrations->type, listed(available)));
  }
}

void check_environment_type(const Experiment& e) {
  const std::string wanted = e.demonstrations->environment_type();
  if (wanted.empty() || wanted == e.config.environment->type) return;
  const ConfigNode* type = e.config.demonstrations->node->find("type");
  throw ConfigError(type->where(), "demonstrations.type",
                    fmt::format("'{}' demonstrates in a '{}' environment, not in '{}'",
                                e.config.demonstrations->type, wanted, e.config.environment->type));
}

void check_images(const Experiment& e) {
  if (!e.context_extractor->needs_images() || e.demonstrations->records_images()) return;
  const Located at = locate_key(*e.config.demonstrations, "images");
  throw ConfigError(
      at.where, at.path,
      fmt::format("the context extractor '{}' reads camera images, but the "
                  "demonstrations of '{}' record none{}",
                  e.config.context->type, e.config.demonstrations->type,
                  e.config.demonstrations->node->find("images") ? ": set images: true" : ""));
}

void check_state_names(const Experiment& e) {
  const std::vector<std::string> observed = e.environment->state_names();
  for (const auto& name : e.context_extractor->state_names()) {
    if (contains(observed, name)) continue;
    const Located at = locate(*e.config.context, name);
    throw ConfigError(at.where, at.path,
                      fmt::format("'{}' is not a state value of '{}' (it observes: {})", name,
                                  e.config.environment->type, listed(observed)));
  }
}

void check_state_source(const Experiment& e) {
  const std::vector<std::string> names = e.context_extractor->state_names();
  if (names.empty()) return;
  const ConfigNode* type = e.config.context->node->find("type");
  throw ConfigError(type->where(), "context.type",
                    fmt::format("'{}' reads state values ({}), but there is no environment "
                                "section to observe them",
                                e.config.context->type, listed(names)));
}

void check_expert(const Experiment& e) {
  if (e.demonstrations->can_demonstrate()) return;
  const ConfigNode* type = e.config.demonstrations->node->find("type");
  throw ConfigError(type->where(), "demonstrations.type",
                    fmt::format("'{}' cannot demonstrate evaluation scenarios, which an "
                                "evaluation in the environment '{}' needs: use the task's expert",
                                e.config.demonstrations->type, e.config.environment->type));
}

struct LocatedNeed {
  MemoryNeed need;
  const ComponentSpec* spec;
};

// The declared sizes must fit in the memory this process may use: refused at load, naming the
// parameter behind the largest need, rather than failing mid-run (or taking the machine down).
void check_memory(const Experiment& e) {
  std::vector<LocatedNeed> needs;
  const Environment* environment = e.environment.get();
  const int64_t longest = e.demonstrations ? e.demonstrations->longest_trajectory(environment) : 0;
  if (e.demonstrations) {
    for (auto& need : e.demonstrations->memory_needs(environment))
      needs.push_back({need, &*e.config.demonstrations});
  }
  if (e.context_extractor) {
    for (auto& need : e.context_extractor->memory_needs())
      needs.push_back({need, &*e.config.context});
  }
  if (e.policy) {
    for (auto& need : e.policy->memory_needs(longest)) needs.push_back({need, &*e.config.policy});
  }
  std::vector<MemoryNeed> plain;
  for (const auto& n : needs) plain.push_back(n.need);
  const MemoryBudget budget = usable_memory();
  const std::optional<size_t> largest = largest_need_beyond(plain, budget);
  if (!largest) return;
  const LocatedNeed& culprit = needs[*largest];
  const ConfigNode& section = *culprit.spec->node;
  throw ConfigError(stated_location(section, culprit.need.key, section.find("type")->where()),
                    culprit.spec->path + "." + culprit.need.key,
                    memory_refusal(plain, *largest, budget));
}

}  // namespace

void check_components(const Experiment& experiment) {
  if (experiment.policy && experiment.demonstrations) check_policy_data(experiment);
  if (experiment.environment && experiment.demonstrations) check_environment_type(experiment);
  if (experiment.context_extractor) check_extractor_segments(experiment);
  if (experiment.context_extractor && experiment.demonstrations) check_images(experiment);
  if (experiment.context_extractor && experiment.environment) check_state_names(experiment);
  if (experiment.context_extractor && !experiment.environment) check_state_source(experiment);
  if (experiment.policy) check_policy_contexts(experiment);
  if (experiment.environment && experiment.demonstrations && experiment.policy) {
    check_expert(experiment);
  }
  check_memory(experiment);
}

}  // namespace corrmp
