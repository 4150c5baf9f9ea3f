// Even sampling of waypoint paths.
#include "envs/corridor_push/path_sampling.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace corrmp {

Eigen::MatrixXd normalised_time(int points) { return Eigen::VectorXd::LinSpaced(points, 0.0, 1.0); }

namespace {

// The slowness-weighted length from the start to each waypoint.
std::vector<double> weighted_arc(const std::vector<Eigen::Vector3d>& waypoints,
                                 const std::vector<double>& slowness) {
  std::vector<double> arc{0.0};
  for (size_t i = 1; i < waypoints.size(); ++i) {
    const double factor = slowness.empty() ? 1.0 : slowness[i - 1];
    arc.push_back(arc.back() + factor * (waypoints[i] - waypoints[i - 1]).norm());
  }
  return arc;
}

}  // namespace

double weighted_length(const std::vector<Eigen::Vector3d>& waypoints,
                       const std::vector<double>& slowness) {
  return waypoints.empty() ? 0.0 : weighted_arc(waypoints, slowness).back();
}

Eigen::MatrixXd sample_path(const std::vector<Eigen::Vector3d>& waypoints, int points,
                            const std::vector<double>& slowness) {
  if (waypoints.empty() || points < static_cast<int>(waypoints.size())) {
    throw std::invalid_argument(
        fmt::format("cannot sample {} waypoints into {} points", waypoints.size(), points));
  }
  if (!slowness.empty() && slowness.size() + 1 != waypoints.size()) {
    throw std::invalid_argument(
        fmt::format("{} slowness factors for {} edges", slowness.size(), waypoints.size() - 1));
  }
  // "arc" is the slowness-weighted length: samples are even in it.
  const std::vector<double> arc = weighted_arc(waypoints, slowness);
  const double length = arc.back();
  Eigen::MatrixXd out(points, 3);
  if (length <= 0.0) {
    for (int j = 0; j < points; ++j) out.row(j) = waypoints.front().transpose();
    return out;
  }
  // Even samples along the arc; each waypoint then replaces its nearest sample.
  std::vector<double> at(points);
  for (int j = 0; j < points; ++j) at[j] = length * j / (points - 1);
  std::vector<bool> pinned(points, false);
  for (size_t i = 0; i < waypoints.size(); ++i) {
    int nearest = static_cast<int>(std::lround(arc[i] / length * (points - 1)));
    while (nearest < points - 1 && pinned[nearest]) ++nearest;
    at[nearest] = arc[i];
    pinned[nearest] = true;
  }
  size_t edge = 0;
  for (int j = 0; j < points; ++j) {
    while (edge + 2 < waypoints.size() && arc[edge + 1] < at[j]) ++edge;
    const double span = arc[edge + 1] - arc[edge];
    const double u = span > 0 ? std::clamp((at[j] - arc[edge]) / span, 0.0, 1.0) : 0.0;
    out.row(j) = ((1 - u) * waypoints[edge] + u * waypoints[edge + 1]).transpose();
  }
  return out;
}

}  // namespace corrmp
