// Registration of the envs module's components: environments and their experts.
#pragma once

#include "core/registry.hpp"
#include "envs/demonstration_source.hpp"
#include "envs/environment.hpp"

namespace corrmp {

void register_builtin_envs(Registry<Environment>& environments,
                           Registry<DemonstrationSource>& demonstrations);

}  // namespace corrmp
