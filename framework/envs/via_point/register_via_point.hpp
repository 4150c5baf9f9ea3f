// Registration of the via_point task's components: its environment and expert.
#pragma once

#include "core/registry.hpp"
#include "envs/demonstration_source.hpp"
#include "envs/environment.hpp"

namespace corrmp {

void register_via_point(Registry<Environment>& environments,
                        Registry<DemonstrationSource>& demonstrations);

}  // namespace corrmp
