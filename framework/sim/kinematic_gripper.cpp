// The kinematic parallel gripper.
#include "sim/kinematic_gripper.hpp"

#include "sim/waypoint_stepping.hpp"

namespace corrmp {

namespace {

SceneBodySpec box_spec(const std::string& name, const std::vector<double>& size,
                       const std::vector<double>& colour) {
  SceneBodySpec spec;
  spec.name = name;
  spec.shape = "box";
  spec.size = size;
  spec.colour = colour;
  spec.friction = 0.5;
  return spec;
}

}  // namespace

KinematicGripper::KinematicGripper(BulletWorld& world, const GripperParams& params,
                                   const Eigen::Vector3d& start)
    : world_(world), params_(params), position_(start) {
  bodies_.push_back(
      world.add_body(box_spec("gripper_palm", params.palm_size, params.colour), true));
  bodies_.push_back(
      world.add_body(box_spec("gripper_finger_left", params.finger_size, params.colour), true));
  bodies_.push_back(
      world.add_body(box_spec("gripper_finger_right", params.finger_size, params.colour), true));
  place_bodies();
}

void KinematicGripper::place_bodies() {
  const double gap = closed_ ? 0.0 : params_.opening;
  const double finger_offset = (gap + params_.finger_size[0]) / 2;
  const double palm_height = (params_.finger_size[2] + params_.palm_size[2]) / 2;
  const Eigen::Vector3d offsets[3] = {
      {0.0, 0.0, palm_height}, {-finger_offset, 0.0, 0.0}, {finger_offset, 0.0, 0.0}};
  for (int i = 0; i < 3; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = position_ + offsets[i];
    world_.set_pose(bodies_[i], pose);
  }
}

void KinematicGripper::set_closed(bool closed) {
  closed_ = closed;
  place_bodies();
}

void KinematicGripper::place(const Eigen::Vector3d& position) {
  position_ = position;
  place_bodies();
}

TrackingResult KinematicGripper::follow(const Eigen::MatrixXd& waypoints,
                                        const std::function<std::string()>& check) {
  return step_through_waypoints(
      waypoints, params_.max_speed * world_.time_step(), position_,
      [&] {
        place_bodies();
        world_.step();
        std::string failure = world_.blow_up();
        if (failure.empty() && check) failure = check();
        return failure;
      },
      [&] { return position_; });
}

}  // namespace corrmp
