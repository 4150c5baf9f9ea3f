// Registration of the envs module's components.
#include "envs/register_builtin.hpp"

#include "envs/corridor_push/corridor_expert.hpp"
#include "envs/corridor_push/corridor_push.hpp"

namespace corrmp {

void register_builtin_envs(Registry<Environment>& environments,
                           Registry<DemonstrationSource>& demonstrations) {
  environments.add<CorridorPushParams>(
      "corridor_push", "push an object through a corridor perturbed along x (Bullet, paper IV-A)",
      [](const CorridorPushParams& p, const BuildContext&) { return new CorridorPush(p); });
  demonstrations.add<CorridorExpertParams>(
      "corridor_expert", "emulated human teacher of corridor_push: push, pull or no correction",
      [](const CorridorExpertParams& p, const BuildContext&) { return new CorridorExpert(p); });
}

}  // namespace corrmp
