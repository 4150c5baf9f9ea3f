// Parameters of the simulated rope-knotting task (paper, Section IV-C,
// "Knotting with the real robot"): a half hitch over a horizontal bar tied by
// two grippers. A weight hangs on the rope's standing end (the load that keeps
// the standing part taut); the right gripper holds the rope near its free end,
// loops it over and around the bar, around the standing part and through the
// loop, and presents the free end; the left gripper encloses the free end (the
// critical point), pulls it through and tightens. Perturbations: where the
// right gripper holds the rope (free tail length), the rope length between the
// weight and the right gripper, the left hand's drift (an offset the hardware
// adds to its executed path) and the right hand's waypoint noise (a small,
// smoothly varying error with which the hardware tracks its rows).
#pragma once

#include <vector>

#include "core/config/field_rule.hpp"
#include "sim/robot/robot_params.hpp"
#include "sim/soft/anchor_gripper.hpp"
#include "sim/soft/rope.hpp"
#include "sim/soft/soft_world.hpp"

namespace corrmp {

// The scripted teacher's choreography, as offsets from the bar centre (m;
// x forward from the robot, y left, z up). The weighted standing part hangs
// from the front of the bar.
struct RopeKnotMotion {
  // Right gripper, holding the rope near its end: over the bar front to back
  // and far down behind it (enough rope for the loop).
  std::vector<double> right_loop{-0.08, 0.0, -0.05, -0.06, 0.0, 0.06,
                                 0.07,  0.0, 0.06,  0.05,  0.0, -0.40};
  // Left gripper takes the standing part below the bar and pulls it forward,
  // opening a large loop: standing part, bar, the rope behind the bar.
  std::vector<double> pinch_approach{-0.017, -0.08, -0.08};
  std::vector<double> pinch{-0.017, 0.0, -0.08};
  std::vector<double> left_pull{-0.12, 0.0, -0.08};
  // Right gripper: forward beside the standing part (+y side), across in front
  // of it below the left gripper (the crossing), up to the loop and through it
  // along +y, then down to present the free end.
  std::vector<double> right_tuck{0.03,  0.06,  -0.15, -0.16, 0.06, -0.15, -0.16, -0.10, -0.15,
                                 -0.08, -0.10, -0.07, -0.08, 0.10, -0.07, -0.10, 0.10,  -0.15};
  // Left gripper lets go of the standing part, backs out and comes to the free
  // end from the -y side.
  std::vector<double> left_retreat{-0.12, -0.10, -0.08};
  std::vector<double> beside_end{-0.10, 0.03, -0.25};
  std::vector<double> nominal_end{-0.10, 0.10, -0.25};
  // Post: pull the end down and away to tighten, release, move clear.
  std::vector<double> tighten{-0.10, 0.10, -0.33};
  std::vector<double> clear{-0.10, 0.10, -0.30};

  template <class Fields>
  void describe(Fields& f) {
    f("right_loop", right_loop,
      "right gripper over the bar, 3 values per point, at least one point (m)");
    f("pinch_approach", pinch_approach, "left gripper before taking the standing part (m)",
      size_is(3));
    f("pinch", pinch, "left gripper taking the standing part (m)", size_is(3));
    f("left_pull", left_pull, "left gripper holding the loop open (m)", size_is(3));
    f("right_tuck", right_tuck,
      "right gripper crossing and tucking, 3 values per point, at least one point (m)");
    f("left_retreat", left_retreat, "left gripper after letting go (m)", size_is(3));
    f("beside_end", beside_end, "left gripper beside the free end (m)", size_is(3));
    f("nominal_end", nominal_end, "left gripper at the critical point (m)", size_is(3));
    f("tighten", tighten, "left gripper at the end of tightening (m)", size_is(3));
    f("clear", clear, "left gripper after releasing (m)", size_is(3));
  }
};

struct RopeKnotParams {
  SoftWorldParams world;
  RopeParams rope;
  AnchorGripperParams gripper;
  std::vector<double> bar_centre{0.45, 0.0, 0.35};
  double bar_radius = 0.0125;
  double bar_length = 0.6;
  double bar_friction = 0.8;
  double load_mass = 0.02;
  double load_arc = 0.06;
  double load_length = 0.04;
  double span = 0.77;
  std::vector<double> right_start_offset{-0.12, -0.05, -0.10};
  std::vector<double> left_start_offset{-0.15, -0.15, -0.10};
  double grasp_range = 0.04;
  double span_range = 0.04;
  std::vector<double> drift_range{0.035, 0.04, 0.03};
  double waypoint_noise = 0.01;
  double waypoint_noise_period = 1.5;
  double settle_time = 0.4;
  double min_winding = 0.75;
  int pre_points = 120;
  int cor_points = 30;
  int post_points = 120;
  RopeKnotMotion motion;
  // Floating grippers, or the dual-arm torso's tools holding the grippers'
  // orientations (rope_knot_scene.hpp).
  RobotParams robot;
  std::vector<double> base_offset_range{0.0, 0.0, 0.0};

  template <class Fields>
  void describe(Fields& f) {
    f("world", world, "Bullet soft-rigid world");
    f("rope", rope, "the rope; its last end_length is coloured");
    f("gripper", gripper, "both anchoring grippers");
    f("bar_centre", bar_centre, "centre of the bar (m); the bar runs along y", size_is(3));
    f("bar_radius", bar_radius, "bar radius (m)", positive());
    f("bar_length", bar_length, "bar length (m)", positive());
    f("bar_friction", bar_friction, "bar friction (times the rope's)", in_range(0.0, 2.0));
    f("load_mass", load_mass, "weight hung on the standing end (kg)", positive());
    f("load_arc", load_arc, "rope length before the weight in the nominal scenario (m)",
      at_least(0.0));
    f("load_length", load_length, "rope length the weight is spread over (m)", positive());
    f("span", span, "nominal rope length between the weight and the right gripper (m)", positive());
    f("right_start_offset", right_start_offset, "right gripper start, from the bar centre (m)",
      size_is(3));
    f("left_start_offset", left_start_offset, "left gripper start, from the bar centre (m)",
      size_is(3));
    f("grasp_range", grasp_range,
      "uniform +- range of where the right gripper holds the rope along it (m)", at_least(0.0));
    f("span_range", span_range, "uniform +- range of the weight-gripper rope length (m)",
      at_least(0.0));
    f("drift_range", drift_range, "uniform +- range of the left hand's drift in x, y, z (m)",
      size_is(3).at_least(0.0));
    f("waypoint_noise", waypoint_noise,
      "uniform +- amplitude per axis of the right hand's tracking error in scenarios with a "
      "noise_seed (m)",
      at_least(0.0));
    f("waypoint_noise_period", waypoint_noise_period,
      "time between the knots the right hand's tracking error is interpolated between (s)",
      positive());
    f("settle_time", settle_time, "time the rope settles after a reset (s)", in_range(0.0, 10.0));
    f("min_winding", min_winding, "turns about the bar a knot must make", at_least(0.0));
    f("pre_points", pre_points, "rows of the pre-MP segment", in_range(2, 10000));
    f("cor_points", cor_points, "rows of the cor-MP segment", in_range(2, 10000));
    f("post_points", post_points, "rows of the post-MP segment", in_range(2, 10000));
    f("motion", motion, "the scripted teacher's choreography");
    f("robot", robot, "what carries the grippers: floating, or dual_arm with its parameters");
    f("base_offset_range", base_offset_range,
      "uniform +- range of the robot base's offset in x, y, z (m; dual_arm only)",
      size_is(3).at_least(0.0));
  }
};

}  // namespace corrmp
