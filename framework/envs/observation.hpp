// What the robot perceives at a critical point: named state values (perfect
// information, paper Section IV-B "perfect context") and the head camera's
// RGB-D image (for the learned contexts of Section III-B).
#pragma once

#include <map>
#include <opencv2/core.hpp>
#include <string>

namespace corrmp {

struct Observation {
  std::map<std::string, double> state;
  cv::Mat rgb;    // CV_8UC3, RGB order; empty when no image was taken
  cv::Mat depth;  // CV_32FC1, metres along the camera axis; 0 where nothing was hit

  double value(const std::string& name) const;  // throws naming the missing entry
};

// A scenario: the stochastic perturbation of one trial (corridor offset, rope
// grasp, ...), as named values.
using Scenario = std::map<std::string, double>;

std::string scenario_json(const Scenario& scenario);

}  // namespace corrmp
