// What the robot perceives at a critical point: named state values (perfect
// information, paper Section IV-B "perfect context") and the head camera's
// RGB-D image with the camera model that took it (for the learned contexts of
// Section III-B and the colour-segmented rope end of Section IV-C).
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "data/camera_model.hpp"

namespace corrmp {

// The pinhole camera an image was taken with: what back-projecting a pixel
// with its depth into the world needs.
struct CameraView {
  CameraIntrinsics intrinsics;
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
};

struct Observation {
  std::map<std::string, double> state;
  cv::Mat rgb;    // CV_8UC3, RGB order; empty when no image was taken
  cv::Mat depth;  // CV_32FC1, metres along the camera axis; 0 where nothing was hit
  std::optional<CameraView> camera;  // set whenever rgb is

  double value(const std::string& name) const;  // throws naming the missing entry
};

// A scenario: the stochastic perturbation of one trial (corridor offset, rope
// grasp, ...), as named values.
using Scenario = std::map<std::string, double>;

std::string scenario_json(const Scenario& scenario);

}  // namespace corrmp
