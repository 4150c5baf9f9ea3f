// Small drawing helpers for the run figures (the autoencoder's reconstructions
// and latents, the evaluation's trajectories), on OpenCV: BGR canvases, text,
// axis ranges, a framed data-to-pixel panel, and PNG writing with clear errors.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <utility>

namespace corrmp {

const cv::Scalar kPlotWhite(255, 255, 255);
const cv::Scalar kPlotGrey(128, 128, 128);
const cv::Scalar kPlotLightGrey(200, 200, 200);
const cv::Scalar kPlotBlack(0, 0, 0);

// Writes `canvas` as PNG; a failed write throws std::runtime_error naming
// `where` and the path.
void write_png(const cv::Mat& canvas, const std::string& path, const char* where);

void put_text(cv::Mat& canvas, const std::string& text, cv::Point origin, double scale = 0.4,
              const cv::Scalar& colour = kPlotBlack);

// [lo, hi] widened to a non-empty range.
std::pair<double, double> padded_range(double lo, double hi);

// A short tick label: 3 significant digits.
std::string tick_label(double value);

// A framed plot area: data coordinates [x_min, x_max] x [y_min, y_max] drawn
// into `pixels` (y up), with min / max tick labels on both axes and a title.
struct PlotPanel {
  cv::Rect pixels;
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;

  cv::Point to_pixel(double x, double y) const;
  // The frame, the end ticks with their labels, the title above and the x
  // label below, drawn in the margins plot_area_in leaves; without
  // `x_end_ticks`, no x tick labels (a categorical axis labels its own).
  void draw_frame(cv::Mat& canvas, const std::string& title, const std::string& x_label,
                  bool x_end_ticks = true) const;
};

// The plot area of a figure cell: the cell less the margins draw_frame's
// labels need (52 px left, 12 right, 24 above, 40 below).
cv::Rect plot_area_in(const cv::Rect& cell);

}  // namespace corrmp
