// Parameters of the push-through-corridor task (paper, Section IV-A): the
// corridor's position is perturbed along the posterior-anterior axis (x, away
// from the robot) uniformly in a 6 cm range; the object is pushed along +y.
#pragma once

#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/bullet_world.hpp"
#include "sim/head_camera.hpp"
#include "sim/kinematic_gripper.hpp"
#include "sim/robot/robot_params.hpp"

namespace corrmp {

struct CorridorPushParams {
  std::string scene = "assets/scenes/corridor.yaml";
  PhysicsParams physics;
  GripperParams gripper;
  RobotParams robot;
  std::vector<double> base_offset_range{0.0, 0.0, 0.0};
  double corridor_range = 0.06;
  double tolerance = 0.006;
  double object_noise = 0.0;
  double pre_push_distance = 0.18;
  double push_height = 0.03;
  double lift_height = 0.07;
  double standoff = 0.02;
  double pass_margin = 0.03;
  int settle_ticks = 60;
  int pre_points = 40;
  int cor_points = 60;
  int post_points = 40;
  HeadCameraParams camera;

  template <class Fields>
  void describe(Fields& f) {
    f("scene", scene, "scene file with table, object, corridor_left and corridor_right");
    f("physics", physics, "Bullet world");
    f("gripper", gripper, "kinematic parallel gripper");
    f("robot", robot, "what moves the gripper: floating, or an arm of the dual-arm torso");
    f("base_offset_range", base_offset_range,
      "uniform +- range of the robot base's offset in x, y, z per scenario (m; dual_arm only): "
      "the table, corridor and object move relative to the robot",
      size_is(3).at_least(0.0));
    f("corridor_range", corridor_range, "corridor offset range along x (m), uniform, centred",
      at_least(0.0));
    f("tolerance", tolerance, "misalignment (m) below which no correction is needed",
      at_least(0.0));
    f("object_noise", object_noise, "uniform noise (m) of the object's start x and y",
      at_least(0.0));
    f("pre_push_distance", pre_push_distance, "how far pre-MP pushes the object along y (m)",
      positive());
    f("push_height", push_height, "tool height while pushing (m)", positive());
    f("lift_height", lift_height, "tool height when moving over the object (m)", positive());
    f("standoff", standoff, "gap kept before contact when approaching (m)", positive());
    f("pass_margin", pass_margin, "how far past the corridor midpoint post-MP pushes (m)",
      at_least(0.0));
    f("settle_ticks", settle_ticks, "physics ticks to let the object rest after a segment",
      in_range(0, 100000));
    f("pre_points", pre_points, "pre-MP trajectory points", in_range(2, 10000));
    f("cor_points", cor_points, "cor-MP trajectory points", in_range(2, 10000));
    f("post_points", post_points, "post-MP trajectory points", in_range(2, 10000));
    f("camera", camera, "head camera");
  }
};

}  // namespace corrmp
