// The via-point reach's paths (rows x, y): straight moves, the bend through a
// via point, resampling at constant speed, and how close a path passes a point.
#pragma once

#include <Eigen/Core>

namespace corrmp {

// `points` rows evenly spaced from `from` to `to`.
Eigen::MatrixXd straight_path(const Eigen::Vector2d& from, const Eigen::Vector2d& to, int points);

// `points` rows from `from` to `to`, evenly spaced in x, bending through
// (their mid x, `via_y`): the straight line plus a sin^2 bump along y whose
// top is the via point, so the path leaves and arrives along the line.
Eigen::MatrixXd bend_path(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double via_y,
                          int points);

// The length of the polyline through the rows of `path`.
double path_length(const Eigen::MatrixXd& path);

// `points` rows evenly spaced by length along the polyline `path` (at least
// two rows): the path walked at constant speed.
Eigen::MatrixXd resample_by_length(const Eigen::MatrixXd& path, int points);

// The shortest distance from `point` to the polyline through the rows of `path`.
double closest_distance(const Eigen::MatrixXd& path, const Eigen::Vector2d& point);

}  // namespace corrmp
