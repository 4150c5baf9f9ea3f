// Registration of the via_point task's components.
#include "envs/via_point/register_via_point.hpp"

#include <memory>

#include "envs/via_point/via_point.hpp"
#include "envs/via_point/via_point_expert.hpp"

namespace corrmp {

void register_via_point(Registry<Environment>& environments,
                        Registry<DemonstrationSource>& demonstrations) {
  environments.add<ViaPointParams>(
      "via_point", "planar reach through a via point offset along y (kinematic, no simulator)",
      [](const ViaPointParams& p, const SeedTree&) { return std::make_unique<ViaPoint>(p); });
  demonstrations.add<ViaPointExpertParams>(
      "via_point_expert",
      "teacher of via_point: straight on, bend through the via point, to the goal",
      [](const ViaPointExpertParams& p, const SeedTree&) {
        return std::make_unique<ViaPointExpert>(p);
      });
}

}  // namespace corrmp
