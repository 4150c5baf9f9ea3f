// Registration of the built-in tasks: one call per task folder under envs/.
#include "envs/register_builtin.hpp"

#include "envs/corridor_push/register_corridor_push.hpp"
#include "envs/rope_knot/register_rope_knot.hpp"

namespace corrmp {

void register_builtin_envs(Registry<Environment>& environments,
                           Registry<DemonstrationSource>& demonstrations) {
  register_corridor_push(environments, demonstrations);
  register_rope_knot(environments, demonstrations);
}

}  // namespace corrmp
