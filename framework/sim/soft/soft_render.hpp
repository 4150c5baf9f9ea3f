// What the head camera sees of the rope task (paper, Section IV-C: the rope end
// is found by colour segmentation of the camera image): the soft world's bars,
// the rope as a tube with its free end in the end colour, and the grippers.
#pragma once

#include <vector>

#include "sim/render/render_scene.hpp"
#include "sim/soft/anchor_gripper.hpp"
#include "sim/soft/rope.hpp"
#include "sim/soft/soft_world.hpp"

namespace corrmp {

struct SoftRenderStyle {
  Eigen::Vector3f bar_colour = Eigen::Vector3f(0.55f, 0.55f, 0.6f);
  Eigen::Vector3f background = Eigen::Vector3f(0.3f, 0.35f, 0.4f);
};

// Appends the rope: body colour up to the first end node, end colour from there.
void add_rope(RenderScene& scene, const Rope& rope);

RenderScene soft_render_scene(const SoftWorld& world, const Rope& rope,
                              const std::vector<const AnchorGripper*>& grippers,
                              const SoftRenderStyle& style = {});

}  // namespace corrmp
