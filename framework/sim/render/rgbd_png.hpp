// Saving head-camera pictures for inspection and for the image data sets the
// autoencoder context is trained on (paper Sec. III-B: 400 camera images).
#pragma once

#include "sim/render/rgbd_image.hpp"

#include <string>

namespace corrmp {

// Writes image.rgb to rgb_path as an 8-bit colour PNG (in the right colour order)
// and, if depth_path is not empty, image.depth as a 16-bit single-channel PNG in
// millimetres (rounded, clamped to 65535; 0 stays "no hit"). Throws
// std::runtime_error naming the file if an image is empty or cannot be written.
void write_png(const RgbdImage& image, const std::string& rgb_path,
               const std::string& depth_path = "");

}  // namespace corrmp
