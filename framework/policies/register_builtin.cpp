// Registration of the policies module's components.
#include "policies/register_builtin.hpp"

#include <memory>

#include "policies/monolithic_cnmp.hpp"
#include "policies/segmented_cnmp.hpp"

namespace corrmp {

void register_builtin_policies(Registry<Policy>& policies) {
  policies.add<SegmentedCnmpParams>(
      "segmented_cnmp", "one CNMP per segment, each conditioned on its start and context (paper)",
      [](const SegmentedCnmpParams& p, const SeedTree& seeds) {
        return std::make_unique<SegmentedCnmp>(p, seeds.seed_for("policy.init"));
      });
  policies.add<MonolithicCnmpParams>(
      "monolithic_cnmp",
      "baseline: one CNMP for the whole trajectory, parameters matched to the segment networks",
      [](const MonolithicCnmpParams& p, const SeedTree& seeds) {
        return std::make_unique<MonolithicCnmp>(p, seeds.seed_for("policy.init"));
      });
}

}  // namespace corrmp
