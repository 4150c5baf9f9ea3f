// Figure of the rope-end segmentation for the run directory's key frames: the head-camera
// picture with the chosen cluster tinted and outlined, its pixel centroid and the located
// 3-D point re-projected (paper, Section IV-C, the knotting context).
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include <optional>

#include "context/color_segmentation/rope_end_locator.hpp"
#include "data/camera_model.hpp"

namespace corrmp {

// rgb (CV_8UC3, R, G, B order) with, when blob is set, its mask blended in green and
// outlined, a cross on its pixel centroid and a yellow circle where its position_world
// projects; if reference_world is set (a true position, in simulation) a cyan circle there.
// Returns a new CV_8UC3 image in B, G, R order, ready for cv::imwrite. Throws
// std::invalid_argument if rgb is not CV_8UC3 or the blob's mask is not CV_8UC1 of its size.
cv::Mat draw_segmentation_overlay(const cv::Mat& rgb, const std::optional<LocatedBlob>& blob,
                                  const CameraIntrinsics& intrinsics,
                                  const Eigen::Isometry3d& world_from_camera,
                                  const std::optional<Eigen::Vector3d>& reference_world = {});

}  // namespace corrmp
