// Render primitives of the rope task's soft world (paper, Section IV-C).
#include "sim/soft/soft_render.hpp"

#include "sim/render/node_chain.hpp"

namespace corrmp {

namespace {

Eigen::Vector3f rgb(const std::vector<double>& colour) {
  return Eigen::Vector3f(colour.at(0), colour.at(1), colour.at(2));
}

}  // namespace

void add_rope(RenderScene& scene, const Rope& rope) {
  const std::vector<Eigen::Vector3d> nodes = rope.nodes();
  const int first_end = rope.first_end_node();
  const std::vector<Eigen::Vector3d> body(nodes.begin(), nodes.begin() + first_end + 1);
  const std::vector<Eigen::Vector3d> end(nodes.begin() + first_end, nodes.end());
  const double radius = rope.params().radius;
  add_node_chain(scene, body, radius, rgb(rope.params().colour));
  add_node_chain(scene, end, radius, rgb(rope.params().end_colour));
}

RenderScene soft_render_scene(const SoftWorld& world, const Rope& rope,
                              const std::vector<const AnchorGripper*>& grippers,
                              const SoftRenderStyle& style) {
  RenderScene scene;
  scene.background = style.background;
  for (const Bar& bar : world.bars()) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
    pose.translation() = bar.centre;
    scene.items.push_back({Cylinder{bar.radius, bar.length / 2}, pose, style.bar_colour});
  }
  add_rope(scene, rope);
  for (const AnchorGripper* gripper : grippers) gripper->add_to(scene);
  return scene;
}

}  // namespace corrmp
