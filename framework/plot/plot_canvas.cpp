// Drawing helpers for run figures (plot_canvas.hpp).
#include "plot/plot_canvas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace corrmp {

void write_png(const cv::Mat& canvas, const std::string& path, const char* where) {
  bool ok = false;
  try {
    ok = cv::imwrite(path, canvas);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(fmt::format("{}: cannot write '{}': {}", where, path, e.what()));
  }
  if (!ok) throw std::runtime_error(fmt::format("{}: cannot write '{}'", where, path));
}

void put_text(cv::Mat& canvas, const std::string& text, cv::Point origin, double scale,
              const cv::Scalar& colour) {
  cv::putText(canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

std::pair<double, double> padded_range(double lo, double hi) {
  if (hi > lo) return {lo, hi};
  const double pad = std::max(1e-9, std::abs(lo) * 0.05 + 0.5);
  return {lo - pad, hi + pad};
}

std::string tick_label(double value) { return fmt::format("{:.3g}", value); }

namespace {

// Margins of a plot area in its cell (plot_area_in).
constexpr int kLeft = 52, kRight = 12, kTop = 24, kBottom = 40;

// Text centred on centre_x within [left, right] at baseline y: at `scale`, or smaller (down to
// 0.3) when it would not fit, so that a long title is not cut off at the cell's edge.
void put_centred_text(cv::Mat& canvas, const std::string& text, int centre_x, int left, int right,
                      int y, double scale) {
  int baseline = 0;
  int width = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline).width;
  if (width > right - left && width > 0) {
    scale = std::max(0.3, scale * (right - left) / width);
    width = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline).width;
  }
  const int x = std::max(left, std::min(centre_x - width / 2, right - width));
  put_text(canvas, text, {x, y}, scale);
}

}  // namespace

cv::Rect plot_area_in(const cv::Rect& cell) {
  return {cell.x + kLeft, cell.y + kTop, cell.width - kLeft - kRight, cell.height - kTop - kBottom};
}

cv::Point PlotPanel::to_pixel(double x, double y) const {
  const double u = (x - x_min) / (x_max - x_min);
  const double v = (y - y_min) / (y_max - y_min);
  return {pixels.x + static_cast<int>(std::lround(u * pixels.width)),
          pixels.y + pixels.height - static_cast<int>(std::lround(v * pixels.height))};
}

void PlotPanel::draw_frame(cv::Mat& canvas, const std::string& title, const std::string& x_label,
                           bool x_end_ticks) const {
  const cv::Point top_left = pixels.tl();
  const cv::Point bottom_right = pixels.br();
  cv::rectangle(canvas, top_left, bottom_right, kPlotBlack, 1);
  // The panel's cell (plot_area_in), less 4 px on each side.
  const int left = top_left.x - kLeft + 4, right = bottom_right.x + kRight - 4;
  const int centre = top_left.x + pixels.width / 2;
  put_centred_text(canvas, title, centre, left, right, top_left.y - 8, 0.45);
  cv::line(canvas, {top_left.x - 4, top_left.y}, top_left, kPlotBlack);
  cv::line(canvas, {top_left.x - 4, bottom_right.y}, {top_left.x, bottom_right.y}, kPlotBlack);
  // The y labels end 6 px left of the axis.
  for (const auto& [value, row] :
       {std::pair{y_max, top_left.y}, std::pair{y_min, bottom_right.y}}) {
    const std::string label = tick_label(value);
    int baseline = 0;
    const int width = cv::getTextSize(label, cv::FONT_HERSHEY_SIMPLEX, 0.4, 1, &baseline).width;
    put_text(canvas, label, {top_left.x - 6 - width, row + 4});
  }
  if (x_end_ticks) {
    cv::line(canvas, {top_left.x, bottom_right.y}, {top_left.x, bottom_right.y + 4}, kPlotBlack);
    cv::line(canvas, bottom_right, {bottom_right.x, bottom_right.y + 4}, kPlotBlack);
    put_text(canvas, tick_label(x_min), {top_left.x - 8, bottom_right.y + 16});
    put_text(canvas, tick_label(x_max), {bottom_right.x - 24, bottom_right.y + 16});
  }
  put_centred_text(canvas, x_label, centre, left, right, bottom_right.y + 32, 0.4);
}

}  // namespace corrmp
