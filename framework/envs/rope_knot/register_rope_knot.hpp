// Registration of the rope_knot task's components (paper, Section IV-C).
#pragma once

#include "core/registry.hpp"
#include "envs/demonstration_source.hpp"
#include "envs/environment.hpp"

namespace corrmp {

void register_rope_knot(Registry<Environment>& environments,
                        Registry<DemonstrationSource>& demonstrations);

}  // namespace corrmp
