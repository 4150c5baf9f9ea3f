// Render primitives of the robot's shapes (robot_render.hpp).
#include "sim/robot/robot_render.hpp"

#include <algorithm>

namespace corrmp {

namespace {

RenderShape render_shape(const RobotShape& shape) {
  switch (shape.kind) {
    case RobotShape::Kind::box:
      return Box{shape.size / 2.0};
    case RobotShape::Kind::cylinder:
      return Cylinder{shape.size.x(), shape.size.y() / 2.0};
    case RobotShape::Kind::sphere:
      break;
  }
  return Sphere{shape.size.x()};
}

}  // namespace

void add_robot(RenderScene& scene, const std::vector<PlacedShape>& shapes,
               const std::vector<std::string>& unseen) {
  for (const PlacedShape& placed : shapes) {
    if (std::find(unseen.begin(), unseen.end(), placed.link) != unseen.end()) continue;
    scene.items.push_back({render_shape(placed.shape), placed.shape.origin, placed.shape.colour});
  }
}

}  // namespace corrmp
