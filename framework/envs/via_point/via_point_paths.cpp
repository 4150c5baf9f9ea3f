// The via-point reach's paths (via_point_paths.hpp).
#include "envs/via_point/via_point_paths.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace corrmp {

Eigen::MatrixXd straight_path(const Eigen::Vector2d& from, const Eigen::Vector2d& to, int points) {
  Eigen::MatrixXd path(points, 2);
  for (int i = 0; i < points; ++i) {
    const double s = points > 1 ? static_cast<double>(i) / (points - 1) : 0.0;
    path.row(i) = (from + s * (to - from)).transpose();
  }
  return path;
}

Eigen::MatrixXd bend_path(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double via_y,
                          int points) {
  Eigen::MatrixXd path = straight_path(from, to, points);
  const double bump = via_y - (from.y() + to.y()) / 2;
  for (int i = 0; i < points; ++i) {
    const double s = points > 1 ? static_cast<double>(i) / (points - 1) : 0.0;
    const double lift = std::sin(M_PI * s);
    path(i, 1) += bump * lift * lift;
  }
  return path;
}

double path_length(const Eigen::MatrixXd& path) {
  double length = 0.0;
  for (Eigen::Index i = 1; i < path.rows(); ++i) length += (path.row(i) - path.row(i - 1)).norm();
  return length;
}

Eigen::MatrixXd resample_by_length(const Eigen::MatrixXd& path, int points) {
  if (path.rows() < 2 || points < 2) {
    throw std::invalid_argument("resample_by_length needs a path and a resampling of two rows");
  }
  std::vector<double> arc{0.0};
  for (Eigen::Index i = 1; i < path.rows(); ++i)
    arc.push_back(arc.back() + (path.row(i) - path.row(i - 1)).norm());
  Eigen::MatrixXd out(points, path.cols());
  size_t edge = 1;
  for (int k = 0; k < points; ++k) {
    const double at = arc.back() * k / (points - 1);
    while (edge + 1 < arc.size() && arc[edge] < at) ++edge;
    const double span = arc[edge] - arc[edge - 1];
    const double f = span > 0 ? std::clamp((at - arc[edge - 1]) / span, 0.0, 1.0) : 0.0;
    out.row(k) = path.row(static_cast<Eigen::Index>(edge - 1)) +
                 f * (path.row(static_cast<Eigen::Index>(edge)) -
                      path.row(static_cast<Eigen::Index>(edge - 1)));
  }
  return out;
}

double closest_distance(const Eigen::MatrixXd& path, const Eigen::Vector2d& point) {
  double closest = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < path.rows(); ++i) {
    const Eigen::Vector2d a = path.row(i).transpose();
    const Eigen::Vector2d b = path.row(std::min(i + 1, path.rows() - 1)).transpose();
    const Eigen::Vector2d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0 ? std::clamp((point - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    closest = std::min(closest, (a + t * ab - point).norm());
  }
  return closest;
}

}  // namespace corrmp
