// Registration of the corridor_push task's components.
#include "envs/corridor_push/register_corridor_push.hpp"

#include <memory>

#include "envs/corridor_push/corridor_expert.hpp"
#include "envs/corridor_push/corridor_push.hpp"

namespace corrmp {

void register_corridor_push(Registry<Environment>& environments,
                            Registry<DemonstrationSource>& demonstrations) {
  environments.add<CorridorPushParams>(
      "corridor_push", "push an object through a corridor perturbed along x (Bullet, paper IV-A)",
      [](const CorridorPushParams& p, const SeedTree&) {
        return std::make_unique<CorridorPush>(p);
      });
  demonstrations.add<CorridorExpertParams>(
      "corridor_expert", "emulated human teacher of corridor_push: push, pull or no correction",
      [](const CorridorExpertParams& p, const SeedTree&) {
        return std::make_unique<CorridorExpert>(p);
      });
}

}  // namespace corrmp
