// Checks of the rope-end segmentation parameters (paper, Section IV-C).
#include "context/color_segmentation/color_segmentation_params.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace corrmp {
namespace {

void check(bool ok, const char* field, const char* rule) {
  if (!ok) {
    throw std::invalid_argument(fmt::format("ColorSegmentationParams: {} {}", field, rule));
  }
}

bool within(double value, double lo, double hi = std::numeric_limits<double>::infinity()) {
  return std::isfinite(value) && value >= lo && value <= hi;
}

}  // namespace

void ColorSegmentationParams::validate() const {
  check(within(hue_centre, 0.0, 360.0), "hue_centre", "must be in [0, 360]");
  check(within(hue_half_width, 0.0, 180.0), "hue_half_width", "must be in [0, 180]");
  check(within(saturation_min, 0.0, 1.0), "saturation_min", "must be in [0, 1]");
  check(within(value_min, 0.0, 1.0), "value_min", "must be in [0, 1]");
  check(morphology_kernel >= 1 && morphology_kernel % 2 == 1, "morphology_kernel",
        "must be odd and >= 1");
  check(min_blob_area >= 1, "min_blob_area", "must be >= 1");
  check(cluster == "largest", "cluster", "must be one of largest");
  check(std::isfinite(max_depth_deviation) && max_depth_deviation > 0.0, "max_depth_deviation",
        "must be > 0");
  check(within(surface_offset, 0.0), "surface_offset", "must be >= 0");
  check(within(rgb_noise_std, 0.0), "rgb_noise_std", "must be >= 0");
  check(within(depth_noise_std, 0.0), "depth_noise_std", "must be >= 0");
}

}  // namespace corrmp
