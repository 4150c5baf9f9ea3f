// Parameters of the via-point reach: a point effector moves in the plane from
// (0, 0) to a goal on the x axis and must pass a via point halfway, whose
// offset along y varies from scenario to scenario (uniform, centred on 0).
// Lengths in metres.
#pragma once

#include "core/config/field_rule.hpp"

namespace corrmp {

struct ViaPointParams {
  double goal_x = 0.3;
  double via_x = 0.15;
  double via_range = 0.06;
  double approach = 0.05;
  double via_tolerance = 0.004;
  double goal_tolerance = 0.004;
  double straight_band = 0.005;
  int pre_points = 30;
  int cor_points = 40;
  int post_points = 30;

  template <class Fields>
  void describe(Fields& f) {
    f("goal_x", goal_x, "the goal's x; the effector starts at x = 0", positive());
    f("via_x", via_x, "the via point's x", positive());
    f("via_range", via_range, "the via point's offset range along y (m), uniform, centred",
      at_least(0.0));
    f("approach", approach,
      "distance along x before the via point where pre-MP ends (the critical point) and "
      "after it where cor-MP ends",
      positive());
    f("via_tolerance", via_tolerance, "how close (m) the path must pass the via point", positive());
    f("goal_tolerance", goal_tolerance, "how close (m) the path must end to the goal", positive());
    f("straight_band", straight_band,
      "a cor-MP bending less than this (m) either way counts as going straight", at_least(0.0));
    f("pre_points", pre_points, "pre-MP trajectory points", in_range(2, 10000));
    f("cor_points", cor_points, "cor-MP trajectory points", in_range(2, 10000));
    f("post_points", post_points, "post-MP trajectory points", in_range(2, 10000));
  }
};

}  // namespace corrmp
