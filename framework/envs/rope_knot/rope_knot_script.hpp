// The emulated human teacher of the rope-knotting task (paper, Section IV-C,
// "Knotting with the real robot"). Pre-MP: the right gripper loops the rope
// over the bar and down behind it; the left gripper takes the weighted
// standing part and pulls it forward, opening a loop; the right gripper
// crosses in front of the standing part, passes the end through the loop and
// presents it; the left gripper lets go and opens where the free end is in the
// nominal scenario (the critical point). Cor-MP: the left gripper moves so
// that the free end is centred in its finger gap. Post-MP: enclose, release the
// right gripper, pull the end down to tighten, release. Segments are rows
// [Lx, Ly, Lz, Lgrip, Rx, Ry, Rz, Rgrip] in commanded coordinates (the scene
// adds the left hand's drift).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "envs/rope_knot/rope_knot_params.hpp"
#include "envs/rope_knot/rope_knot_scene.hpp"

namespace corrmp {

// The 8-column rows through `keyframes` resampled to `points` rows, evenly
// spaced along the larger of the two grippers' paths (a grip change counts as
// a short pause so that it keeps its place); grips are interpolated (the
// scene thresholds them at 0.5).
Eigen::MatrixXd resample_rows(const std::vector<Eigen::Matrix<double, 8, 1>>& keyframes,
                              int points);

// Nominal pre-MP, the same for every scenario; ends at the critical point.
Eigen::MatrixXd pre_waypoints(const RopeKnotParams& params);

// The displacement of the left gripper that centres the free end in its gap.
Eigen::Vector3d correction_offset(const RopeKnotScene& scene);

// The cor-MP: the left gripper moves by `offset` in a straight line from its
// commanded position, grippers keep their grips; the right columns are the
// nominal critical-point ones.
Eigen::MatrixXd correction_waypoints(const RopeKnotScene& scene, const Eigen::Vector3d& offset);

// Post-MP from the left gripper's commanded position at the critical point
// (after any correction): enclose, release the right gripper, pull the end
// down by the fixed displacement tighten - nominal_end, release, move clear.
Eigen::MatrixXd post_waypoints(const RopeKnotParams& params, const Eigen::Vector3d& left_start);

// One scripted trial: reset, pre-MP, the correction (when `correct`), post-MP.
// `misalignment`, when given, receives the end offset at the critical point.
RopeKnotOutcome scripted_trial(RopeKnotScene& scene, const Scenario& scenario, bool correct,
                               Eigen::Vector3d* misalignment = nullptr);

}  // namespace corrmp
