// Registration of the cnmp module's components.
#include "cnmp/register_builtin.hpp"

#include <memory>

#include "cnmp/curve_family.hpp"
#include "cnmp/trajectory_files.hpp"

namespace corrmp {

void register_builtin_cnmp(Registry<DemonstrationSource>& demonstrations) {
  demonstrations.add<CurveFamilyParams>(
      "curve_family", "synthetic 1-D curves parameterised by a context value (no simulation)",
      [](const CurveFamilyParams& p, const SeedTree&) { return std::make_unique<CurveFamily>(p); });
  demonstrations.add<TrajectoryFilesParams>(
      "trajectory_files", "recorded demonstrations from .npy ([N, T, D]) or CSV files",
      [](const TrajectoryFilesParams& p, const SeedTree&) {
        return std::make_unique<TrajectoryFiles>(p, load_trajectory_files(p));
      });
}

}  // namespace corrmp
