// Registration of the policies module's components.
#pragma once

#include "core/registry.hpp"
#include "policies/policy.hpp"

namespace corrmp {

void register_builtin_policies(Registry<Policy>& policies);

}  // namespace corrmp
