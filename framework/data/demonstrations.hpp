// Demonstrations: per-segment trajectories of a skill as the human (or its
// emulating expert) showed them, cut at the critical points into pre-MP, cor-MP
// and post-MP (paper, Section III "Method"). A single-segment demonstration is
// the monolithic case. Where they come from: envs/demonstration_source.hpp.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "core/seeds.hpp"
#include "data/observation.hpp"

namespace corrmp {

// One segment of one demonstration. Row t of `x` holds the CNMP inputs of time
// step t (column 0 is time normalised to [0, 1], further columns task
// parameters), row t of `y` the outputs (for example gripper x, y, z in m).
struct SegmentTrajectory {
  std::string segment;  // "pre", "cor", "post", "full", ...
  Eigen::MatrixXd x;
  Eigen::MatrixXd y;
  Eigen::VectorXd context;  // the segment's context vector; may be empty
  Observation start;        // what was observed at the segment's start (critical point)
  // The segment's span in the whole skill's normalised time (its critical
  // points in a monolithic recording of the same demonstration); NaN where
  // the source does not know it.
  double phase_begin = std::numeric_limits<double>::quiet_NaN();
  double phase_end = std::numeric_limits<double>::quiet_NaN();
};

struct Demonstration {
  std::string scenario;  // JSON describing what was demonstrated
  std::vector<SegmentTrajectory> segments;
  std::string decision;  // the decision made at the critical point (a TaskReport label) where known

  const SegmentTrajectory* find(const std::string& segment) const {
    for (const auto& s : segments) {
      if (s.segment == segment) return &s;
    }
    return nullptr;
  }
};

struct DemonstrationSplit {
  std::vector<Demonstration> train;
  std::vector<Demonstration> validation;
};

}  // namespace corrmp
