// Turning an expert's waypoint path into a demonstration trajectory of a fixed
// number of points, evenly spaced along the path with every waypoint (corner)
// kept exactly, and time normalised to [0, 1] (paper, Section III-A: CNMPs are
// queried at normalised time).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace corrmp {

// `points` rows of the path through `waypoints` (rows x, y, z). Needs points >=
// the number of waypoints. A path of zero length repeats its point. `slowness`
// (one factor per edge, default 1) gives an edge proportionally more points, as
// a demonstrator moves slowly while in contact.
Eigen::MatrixXd sample_path(const std::vector<Eigen::Vector3d>& waypoints, int points,
                            const std::vector<double>& slowness = {});

// The slowness-weighted length of the path (its duration at unit speed).
double weighted_length(const std::vector<Eigen::Vector3d>& waypoints,
                       const std::vector<double>& slowness = {});

// Column of `points` times evenly spaced in [0, 1].
Eigen::MatrixXd normalised_time(int points);

}  // namespace corrmp
