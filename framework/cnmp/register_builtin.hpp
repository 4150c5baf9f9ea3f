// Registration of the cnmp module's components (demonstration sources from
// synthetic curves and files, CNMP policies).
#pragma once

#include "core/registry.hpp"
#include "envs/demonstration_source.hpp"

namespace corrmp {

void register_builtin_cnmp(Registry<DemonstrationSource>& demonstrations);

}  // namespace corrmp
