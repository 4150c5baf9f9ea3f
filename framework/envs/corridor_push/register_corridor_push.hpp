// Registration of the corridor_push task's components (paper, Section IV-A).
#pragma once

#include "core/registry.hpp"
#include "envs/demonstration_source.hpp"
#include "envs/environment.hpp"

namespace corrmp {

void register_corridor_push(Registry<Environment>& environments,
                            Registry<DemonstrationSource>& demonstrations);

}  // namespace corrmp
