// What the simulated head camera sees, as plain data: a list of coloured primitives
// (boxes, cylinders, capsules, spheres) posed in the world frame. The robot observes
// the table-top scene with its head camera (paper Sec. IV-A: images after the
// pre-critical primitive feed the "Learning the Context" autoencoder of Sec. III-B;
// Sec. IV-C: the rope end is colour-segmented from an RGB-D image). The simulation
// fills a RenderScene each time it takes a picture; OffscreenRenderer draws it.
#pragma once

#include <Eigen/Geometry>

#include <variant>
#include <vector>

namespace corrmp {

// Axis-aligned box in its own frame, centred on the origin.
struct Box {
  Eigen::Vector3d half_extents = Eigen::Vector3d::Constant(0.5);
};

// Closed cylinder centred on the origin; its axis is the local z axis.
struct Cylinder {
  double radius = 0.5;
  double half_height = 0.5;  // the flat caps are at z = +-half_height
};

// Cylinder of half height half_height along local z with a hemisphere of the same
// radius on each end (total length 2 * (half_height + radius)).
struct Capsule {
  double radius = 0.5;
  double half_height = 0.5;  // the hemisphere centres are at z = +-half_height
};

// Sphere centred on the origin.
struct Sphere {
  double radius = 0.5;
};

using RenderShape = std::variant<Box, Cylinder, Capsule, Sphere>;

// One primitive to draw: pose maps shape coordinates to world coordinates.
struct RenderItem {
  RenderShape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Vector3f colour = Eigen::Vector3f::Constant(0.5f);  // RGB in [0, 1]
};

// Everything in view, plus the colour of pixels where nothing is hit.
struct RenderScene {
  std::vector<RenderItem> items;
  Eigen::Vector3f background = Eigen::Vector3f::Zero();  // RGB in [0, 1]
};

}  // namespace corrmp
