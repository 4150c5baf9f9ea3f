// The robot as the task's camera sees it: its collision shapes at their
// executed poses, in their links' colours, as render primitives.
#pragma once

#include <string>
#include <vector>

#include "sim/render/render_scene.hpp"
#include "sim/robot/dual_arm.hpp"

namespace corrmp {

// Appends every shape except those of the links named in `unseen`.
void add_robot(RenderScene& scene, const std::vector<PlacedShape>& shapes,
               const std::vector<std::string>& unseen = {});

}  // namespace corrmp
