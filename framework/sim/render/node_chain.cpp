// Rope node chains as render primitives (see node_chain.hpp).
#include "sim/render/node_chain.hpp"

#include <stdexcept>

namespace corrmp {

Eigen::Isometry3d segment_pose(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const Eigen::Vector3d axis = to - from;
  if (axis.norm() <= 0.0) throw std::invalid_argument("segment_pose: the two points coincide");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
  pose.translation() = 0.5 * (from + to);
  return pose;
}

void add_node_chain(RenderScene& scene, const std::vector<Eigen::Vector3d>& nodes, double radius,
                    const Eigen::Vector3f& colour, ChainStyle style) {
  if (!(radius > 0.0)) throw std::invalid_argument("add_node_chain: radius must be positive");
  const auto add_sphere = [&](const Eigen::Vector3d& centre) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = centre;
    scene.items.push_back({Sphere{radius}, pose, colour});
  };
  if (style == ChainStyle::kSpheres || nodes.size() == 1) {
    for (const Eigen::Vector3d& node : nodes) add_sphere(node);
    return;
  }
  for (size_t i = 1; i < nodes.size(); ++i) {
    const double length = (nodes[i] - nodes[i - 1]).norm();
    if (length <= 0.0) {
      add_sphere(nodes[i]);
      continue;
    }
    scene.items.push_back(
        {Capsule{radius, 0.5 * length}, segment_pose(nodes[i - 1], nodes[i]), colour});
  }
}

}  // namespace corrmp
