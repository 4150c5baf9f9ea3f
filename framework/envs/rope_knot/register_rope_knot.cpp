// Registration of the rope_knot task's components.
#include "envs/rope_knot/register_rope_knot.hpp"

#include <memory>

#include "envs/rope_knot/rope_expert.hpp"
#include "envs/rope_knot/rope_knot.hpp"

namespace corrmp {

void register_rope_knot(Registry<Environment>& environments,
                        Registry<DemonstrationSource>& demonstrations) {
  environments.add<RopeKnotEnvironmentParams>(
      "rope_knot", "two grippers tie a half hitch of a soft rope over a bar (Bullet, paper IV-C)",
      [](const RopeKnotEnvironmentParams& p, const SeedTree&) {
        return std::make_unique<RopeKnot>(p);
      });
  demonstrations.add<RopeExpertParams>(
      "rope_expert",
      "emulated teleoperator of rope_knot: pre-MP, a correction onto the rope end, post-MP",
      [](const RopeExpertParams& p, const SeedTree&) { return std::make_unique<RopeExpert>(p); });
}

}  // namespace corrmp
