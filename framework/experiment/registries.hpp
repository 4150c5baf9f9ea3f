// Every component registry, filled by one explicit register_builtin_*() per
// module. docs/architecture.md, "Components".
#pragma once

#include <string>

#include "context/context_extractor.hpp"
#include "core/registry.hpp"
#include "envs/demonstration_source.hpp"
#include "envs/environment.hpp"
#include "policies/policy.hpp"

namespace corrmp {

struct Registries {
  Registry<Environment> environments{"environment"};
  Registry<DemonstrationSource> demonstrations{"demonstration source"};
  Registry<ContextExtractor> contexts{"context extractor"};
  Registry<Policy> policies{"policy"};
};

// The registries with every built-in component registered.
Registries builtin_registries();

// The text of `run_experiment --list`: each registry, its entries with a
// one-line description, and each entry's parameters.
std::string describe_registries(const Registries& registries);

}  // namespace corrmp
