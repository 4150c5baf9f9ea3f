// The gripper carried by an arm.
#include "sim/robot/arm_gripper.hpp"

#include <algorithm>

#include "sim/waypoint_stepping.hpp"

namespace corrmp {

namespace {

Arm other(Arm arm) { return arm == Arm::left ? Arm::right : Arm::left; }

SceneBodySpec body_of(const PlacedShape& placed, int index) {
  SceneBodySpec spec;
  spec.name = placed.link + "_shape_" + std::to_string(index);
  const RobotShape& shape = placed.shape;
  switch (shape.kind) {
    case RobotShape::Kind::box:
      spec.shape = "box";
      spec.size = {shape.size.x(), shape.size.y(), shape.size.z()};
      break;
    case RobotShape::Kind::cylinder:
      spec.shape = "cylinder";
      spec.size = {shape.size.x(), shape.size.y()};
      break;
    case RobotShape::Kind::sphere:
      spec.shape = "sphere";
      spec.size = {shape.size.x()};
      break;
  }
  spec.colour = {shape.colour.x(), shape.colour.y(), shape.colour.z()};
  spec.friction = 0.5;
  return spec;
}

}  // namespace

ArmGripper::ArmGripper(BulletWorld& world, const GripperParams& params, DualArm& robot, Arm arm)
    : world_(world),
      params_(params),
      robot_(robot),
      arm_(arm),
      hold_(robot.tool_position(other(arm))),
      commanded_(robot.tool_position(arm)),
      gripper_(world, params, robot.tool_position(arm)) {
  std::vector<std::string> links = robot.arm_links(Arm::left);
  const std::vector<std::string>& right = robot.arm_links(Arm::right);
  links.insert(links.end(), right.begin(), right.end());
  const std::vector<std::string>& hand = robot.hand_links(arm);
  const std::vector<PlacedShape> shapes = robot.shapes();
  for (size_t s = 0; s < shapes.size(); ++s) {
    const std::string& link = shapes[s].link;
    const bool shown = std::find(links.begin(), links.end(), link) != links.end() &&
                       std::find(hand.begin(), hand.end(), link) == hand.end();
    shown_.push_back(shown);
    if (shown) arm_bodies_.push_back(world.add_body(body_of(shapes[s], static_cast<int>(s)), true));
  }
  place_bodies();
}

void ArmGripper::place_bodies() {
  gripper_.place(robot_.tool_position(arm_));
  const std::vector<Eigen::Isometry3d> poses = robot_.shape_poses();
  placed_.resize(poses.size());
  size_t body = 0;
  for (size_t s = 0; s < poses.size(); ++s) {
    if (!shown_[s]) continue;
    // A body left where it is moves exactly as one placed there again.
    if (!placed_[s] || placed_[s]->matrix() != poses[s].matrix()) {
      world_.set_pose(arm_bodies_[body], poses[s]);
      placed_[s] = poses[s];
    }
    ++body;
  }
}

TrackingResult ArmGripper::follow(const Eigen::MatrixXd& waypoints,
                                  const std::function<std::string()>& check) {
  return step_through_waypoints(
      waypoints, params_.max_speed * world_.time_step(), commanded_,
      [&] {
        std::string failure =
            arm_ == Arm::left ? robot_.track(commanded_, hold_) : robot_.track(hold_, commanded_);
        if (!failure.empty()) return failure;
        place_bodies();
        world_.step();
        failure = world_.blow_up();
        if (failure.empty() && check) failure = check();
        return failure;
      },
      [&] { return position(); });
}

}  // namespace corrmp
