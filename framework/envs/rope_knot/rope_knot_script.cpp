// The scripted teacher of the rope-knotting task (paper, Section IV-C).
#include "envs/rope_knot/rope_knot_script.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace corrmp {

namespace {

using Row = Eigen::Matrix<double, 8, 1>;

Eigen::Vector3d bar(const RopeKnotParams& params) {
  return Eigen::Vector3d(params.bar_centre.at(0), params.bar_centre.at(1), params.bar_centre.at(2));
}

Eigen::Vector3d point(const std::vector<double>& v, size_t k = 0) {
  if (v.size() < 3 * (k + 1)) throw std::invalid_argument("RopeKnotMotion: a point needs 3 values");
  return Eigen::Vector3d(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
}

std::vector<Eigen::Vector3d> points(const std::vector<double>& v, const char* what) {
  if (v.empty() || v.size() % 3 != 0) {
    throw std::invalid_argument(fmt::format("RopeKnotMotion::{}: needs 3 values per point", what));
  }
  std::vector<Eigen::Vector3d> out;
  for (size_t k = 0; k < v.size() / 3; ++k) out.push_back(point(v, k));
  return out;
}

// Right gripper at the critical point (nominal).
Eigen::Vector3d right_end(const RopeKnotParams& params) {
  return bar(params) + points(params.motion.right_tuck, "right_tuck").back();
}

Row row(const Eigen::Vector3d& left, double left_grip, const Eigen::Vector3d& right,
        double right_grip) {
  Row r;
  r << left, left_grip, right, right_grip;
  return r;
}

}  // namespace

Eigen::MatrixXd resample_rows(const std::vector<Row>& keyframes, int points) {
  if (keyframes.size() < 2 || points < 2) {
    throw std::invalid_argument("resample_rows: needs 2 keyframes and 2 points");
  }
  constexpr double kGripPause = 0.02;  // path length a grip change counts for (m)
  std::vector<double> u{0.0};
  for (size_t k = 1; k < keyframes.size(); ++k) {
    const Row d = keyframes[k] - keyframes[k - 1];
    const double move = std::max(d.segment<3>(0).norm(), d.segment<3>(4).norm());
    const double grip = std::max(std::abs(d(3)), std::abs(d(7))) > 0 ? kGripPause : 0.0;
    u.push_back(u.back() + move + grip);
  }
  Eigen::MatrixXd rows(points, 8);
  size_t k = 0;
  for (int i = 0; i < points; ++i) {
    const double s = u.back() * i / (points - 1);
    while (k + 2 < keyframes.size() && s > u[k + 1]) ++k;
    const double length = u[k + 1] - u[k];
    const double a = length > 0 ? std::clamp((s - u[k]) / length, 0.0, 1.0) : 1.0;
    rows.row(i) = ((1 - a) * keyframes[k] + a * keyframes[k + 1]).transpose();
  }
  return rows;
}

Eigen::MatrixXd pre_waypoints(const RopeKnotParams& params) {
  const Eigen::Vector3d b = bar(params);
  const RopeKnotMotion& m = params.motion;
  const Eigen::Vector3d left0 = b + point(params.left_start_offset);
  const Eigen::Vector3d right0 = b + point(params.right_start_offset);
  std::vector<Row> keys{row(left0, 0, right0, 1)};
  Eigen::Vector3d right = right0;
  for (const auto& p : points(m.right_loop, "right_loop")) {
    right = b + p;
    keys.push_back(row(left0, 0, right, 1));
  }
  keys.push_back(row(b + point(m.pinch_approach), 0, right, 1));
  keys.push_back(row(b + point(m.pinch), 0, right, 1));
  keys.push_back(row(b + point(m.pinch), 1, right, 1));
  const Eigen::Vector3d hold = b + point(m.left_pull);
  keys.push_back(row(hold, 1, right, 1));
  for (const auto& p : points(m.right_tuck, "right_tuck")) {
    right = b + p;
    keys.push_back(row(hold, 1, right, 1));
  }
  keys.push_back(row(hold, 0, right, 1));
  for (const auto* p : {&m.left_retreat, &m.beside_end, &m.nominal_end}) {
    keys.push_back(row(b + point(*p), 0, right, 1));
  }
  return resample_rows(keys, params.pre_points);
}

Eigen::Vector3d correction_offset(const RopeKnotScene& scene) { return scene.end_offset(); }

Eigen::MatrixXd correction_waypoints(const RopeKnotScene& scene, const Eigen::Vector3d& offset) {
  const RopeKnotParams& params = scene.params();
  const Eigen::Vector3d right = right_end(params);
  const Eigen::Vector3d left = scene.left_command();
  return resample_rows({row(left, 0, right, 1), row(left + offset, 0, right, 1)},
                       params.cor_points);
}

Eigen::MatrixXd post_waypoints(const RopeKnotParams& params, const Eigen::Vector3d& left_start) {
  const Eigen::Vector3d b = bar(params);
  const RopeKnotMotion& m = params.motion;
  const Eigen::Vector3d right = right_end(params);
  // The pull is relative to where the end was enclosed: a fixed displacement
  // tightens the same whatever the tail length.
  const Eigen::Vector3d shift = left_start - (b + point(m.nominal_end));
  const Eigen::Vector3d tight = b + point(m.tighten) + shift;
  const Eigen::Vector3d clear = b + point(m.clear) + shift;
  std::vector<Row> keys{row(left_start, 0, right, 1), row(left_start, 1, right, 1),
                        row(left_start, 1, right, 0), row(tight, 1, right, 0),
                        row(tight, 0, right, 0),      row(clear, 0, right, 0)};
  return resample_rows(keys, params.post_points);
}

RopeKnotOutcome scripted_trial(RopeKnotScene& scene, const Scenario& scenario, bool correct,
                               Eigen::Vector3d* misalignment) {
  scene.reset(scenario);
  std::string fault = scene.execute(pre_waypoints(scene.params()));
  if (misalignment != nullptr) *misalignment = scene.end_offset();
  if (fault.empty() && correct) {
    fault = scene.execute(correction_waypoints(scene, correction_offset(scene)));
  }
  if (fault.empty()) scene.execute(post_waypoints(scene.params(), scene.left_command()));
  return scene.outcome();
}

}  // namespace corrmp
