// Locating the rope end in the head camera's RGB-D image, the context of the knotting
// correction network: "a straightforward color-segmentation and clustering pipeline on the
// RGB-D image captured by the camera mounted on the head" (paper, Section IV-C).
// Pipeline: HSV threshold -> morphological opening and closing -> connected components ->
// the largest cluster -> its pixels back-projected with their (outlier-filtered) depth ->
// centroid pushed back from the seen surface towards the rope's centre line.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include <optional>

#include "context/color_segmentation/color_segmentation_params.hpp"
#include "data/camera_model.hpp"

namespace corrmp {

struct LocatedBlob {
  Eigen::Vector3d position_world = Eigen::Vector3d::Zero();  // centre-line estimate (m)
  Eigen::Vector2d pixel_centroid = Eigen::Vector2d::Zero();  // (u, v) of the cluster's pixels
  int pixel_count = 0;                                       // pixels in the chosen cluster
  int depth_pixel_count = 0;  // of those, back-projected (valid depth near the median)
  cv::Mat mask;               // CV_8UC1, image size, 255 on the chosen cluster, 0 elsewhere
};

// The colour-thresholded mask before clustering (after opening and closing): CV_8UC1,
// 255 where a pixel's HSV colour passes the params' hue window, saturation and value minima.
cv::Mat colour_mask(const cv::Mat& rgb, const ColorSegmentationParams& params);

// Finds the largest cluster of the params' colour in rgb (CV_8UC3, R, G, B order) of at least
// params.min_blob_area pixels and locates it in the world with depth (CV_32FC1, metres along
// the optical axis, 0 = nothing): the mean of the back-projections of its pixels whose depth
// is within params.max_depth_deviation of the cluster's median depth, moved
// params.surface_offset further along the viewing ray. Nothing when no cluster is large
// enough or none of its pixels has a depth. Throws std::invalid_argument for wrong image
// types, sizes differing from each other or from the intrinsics, or bad params.
std::optional<LocatedBlob> locate_colour_blob(const cv::Mat& rgb, const cv::Mat& depth,
                                              const CameraIntrinsics& intrinsics,
                                              const Eigen::Isometry3d& world_from_camera,
                                              const ColorSegmentationParams& params);

}  // namespace corrmp
