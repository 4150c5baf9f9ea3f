// Parameters of the rope-end colour segmentation: the context of the knotting correction
// is the rope end's position, found "with a straightforward color-segmentation and
// clustering pipeline on the RGB-D image" of the head camera (paper, Section IV-C).
// HSV thresholds pick the end's colour, morphology cleans the mask, connected components
// cluster it, and the chosen cluster's pixels are back-projected with their depth.
#pragma once

#include <string>

#include "core/config/field_rule.hpp"

namespace corrmp {

struct ColorSegmentationParams {
  // Hue window centred on hue_centre, +- hue_half_width, measured on the colour circle,
  // so a red window (centre 0) also takes hues just below 360.
  double hue_centre = 0.0;       // degrees
  double hue_half_width = 15.0;  // degrees
  double saturation_min = 0.5;   // HSV saturation in [0, 1]
  double value_min = 0.2;        // HSV value (brightness) in [0, 1]
  // Side of the elliptic kernel of the opening (removes specks) and closing (fills holes)
  // of the mask; odd, 1 disables cleaning.
  int morphology_kernel = 3;
  int min_blob_area = 10;           // px: smaller clusters are ignored
  std::string cluster = "largest";  // which connected component is the rope end
  // Pixels of the cluster whose depth is farther than this from the cluster's median depth
  // are not back-projected (edges seen against the background or objects behind).
  double max_depth_deviation = 0.03;  // m
  // The camera sees the rope's surface: the located point is pushed back along the viewing
  // ray by this distance to reach the centre line. For a tube seen side-on the mean depth of
  // its visible half is pi/4 of the radius in front of the axis; the radius is the nearest
  // surface point.
  double surface_offset = 0.0;  // m
  // Simulated camera noise, applied by add_camera_noise (0 = off).
  double rgb_noise_std = 0.0;    // Gaussian, per channel, in 0-255 units
  double depth_noise_std = 0.0;  // Gaussian, on pixels with depth, metres

  template <class Fields>
  void describe(Fields& f) {
    f("hue_centre", hue_centre, "centre of the hue window (degrees)", in_range(0.0, 360.0));
    f("hue_half_width", hue_half_width, "half width of the hue window (degrees)",
      in_range(0.0, 180.0));
    f("saturation_min", saturation_min, "smallest HSV saturation kept", in_range(0.0, 1.0));
    f("value_min", value_min, "smallest HSV value kept", in_range(0.0, 1.0));
    f("morphology_kernel", morphology_kernel, "opening/closing kernel side (px, odd)", at_least(1));
    f("min_blob_area", min_blob_area, "smallest cluster taken (px)", at_least(1));
    f("cluster", cluster, "which connected component is the object", one_of({"largest"}));
    f("max_depth_deviation", max_depth_deviation, "depth outlier bound around the median (m)",
      positive());
    f("surface_offset", surface_offset, "push back along the viewing ray to the centre line (m)",
      at_least(0.0));
    f("rgb_noise_std", rgb_noise_std, "Gaussian RGB noise std (0-255 units)", at_least(0.0));
    f("depth_noise_std", depth_noise_std, "Gaussian depth noise std (m)", at_least(0.0));
  }

  // Throws std::invalid_argument naming the first bad field (the describe() rules, plus an
  // odd morphology kernel and finite values), for parameters not read from a config.
  void validate() const;
};

}  // namespace corrmp
