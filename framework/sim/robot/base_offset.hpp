// The workspace perturbation of a task on the arms: the robot's base moved in
// each scenario by a uniform offset within +- range per axis (scenario keys
// base_dx, base_dy, base_dz), the task's scene staying where it is in the world.
#pragma once

#include <vector>

#include "core/seeds.hpp"
#include "data/observation.hpp"
#include "sim/robot/dual_arm.hpp"

namespace corrmp {

// Whether `range` (x, y, z in m) moves the base at all.
bool moves_base(const std::vector<double>& range);

// Draws the three keys into `scenario` when moves_base(range), and nothing
// otherwise, so that the stream's other draws stay as they were; call it after
// the task's other draws. `range` has three entries.
void draw_base_offset(const std::vector<double>& range, Rng& rng, Scenario& scenario);

// `params` with the base moved by the scenario's keys (a missing key is 0).
DualArmParams with_base_offset(DualArmParams params, const Scenario& scenario);

}  // namespace corrmp
