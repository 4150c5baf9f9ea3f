// Simulated camera noise for the rope-end segmentation: the real head camera's RGB-D image
// (paper, Section IV-C) is noisy, so the simulated one can be perturbed before segmenting.
#pragma once

#include <opencv2/core.hpp>

#include "context/color_segmentation/color_segmentation_params.hpp"
#include "core/seeds.hpp"

namespace corrmp {

// Adds Gaussian noise in place: params.rgb_noise_std (0-255 units) to every channel of rgb
// (CV_8UC3, rounded and saturated to [0, 255]), then params.depth_noise_std (metres) to every
// pixel of depth (CV_32FC1) that has a depth; pixels with depth 0 ("nothing") stay 0 and a
// noisy depth is kept above 0. A zero std leaves that image untouched and draws nothing from
// rng; otherwise the draws go row by row, so the same rng state gives the same images.
// Throws std::invalid_argument for wrong types, different sizes or bad params.
void add_camera_noise(cv::Mat& rgb, cv::Mat& depth, const ColorSegmentationParams& params,
                      Rng& rng);

}  // namespace corrmp
