// Drawing a rope: the simulated rope is a chain of soft-body nodes (paper Sec. IV-C, the
// rope-knotting experiment whose context is the rope end found by colour segmentation).
// These helpers turn the node positions into render primitives.
#pragma once

#include "sim/render/render_scene.hpp"

#include <Eigen/Core>

#include <vector>

namespace corrmp {

enum class ChainStyle {
  kCapsules,  // a capsule between each pair of consecutive nodes: a smooth tube
  kSpheres,   // one sphere per node: beads
};

// Pose of a capsule (or cylinder) whose local z axis runs from `from` to `to`, centred
// half-way. Together with half_height = |to - from| / 2 the capsule's hemisphere
// centres land exactly on the two points. Throws std::invalid_argument if from == to.
Eigen::Isometry3d segment_pose(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

// Appends the chain through `nodes` (in order) to scene.items, every primitive with the
// given radius and colour. With kCapsules, consecutive coincident nodes are drawn as a
// sphere, and a single node as a sphere. Throws std::invalid_argument if radius <= 0.
void add_node_chain(RenderScene& scene, const std::vector<Eigen::Vector3d>& nodes, double radius,
                    const Eigen::Vector3f& colour, ChainStyle style = ChainStyle::kCapsules);

}  // namespace corrmp
