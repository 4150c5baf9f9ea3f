// Drawing data on a PlotPanel (plot_lines.hpp).
#include "plot/plot_lines.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace corrmp {

namespace {

// Dash and gap lengths in pixels of a dashed line.
constexpr double kDash = 8.0, kGap = 5.0;

// Draws the segment a-b dashed, continuing the pattern from `phase` (pixels
// already drawn along the line); returns the new phase.
double dashed_segment(cv::Mat& canvas, cv::Point a, cv::Point b, const cv::Scalar& colour,
                      int thickness, double phase) {
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  if (length == 0.0) return phase;
  double at = 0.0;
  while (at < length) {
    const double in_period = std::fmod(phase + at, kDash + kGap);
    const double step = in_period < kDash ? kDash - in_period : kDash + kGap - in_period;
    const double end = std::min(length, at + step);
    if (in_period < kDash) {
      const auto point = [&](double s) {
        return cv::Point(static_cast<int>(std::lround(a.x + (b.x - a.x) * s / length)),
                         static_cast<int>(std::lround(a.y + (b.y - a.y) * s / length)));
      };
      cv::line(canvas, point(at), point(end), colour, thickness, cv::LINE_AA);
    }
    at = end;
  }
  return phase + length;
}

bool finite_point(double x, double y) { return std::isfinite(x) && std::isfinite(y); }

}  // namespace

cv::Scalar series_colour(size_t index) {
  static const cv::Scalar kPalette[] = {
      {180, 119, 31}, {14, 127, 255},  {44, 160, 44},   {40, 39, 214},  {189, 103, 148},
      {75, 86, 140},  {194, 119, 227}, {127, 127, 127}, {34, 189, 188}, {207, 190, 23}};
  return kPalette[index % (sizeof(kPalette) / sizeof(kPalette[0]))];
}

int text_width(const std::string& text, double scale) {
  int baseline = 0;
  return cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline).width;
}

void draw_polyline(cv::Mat& canvas, const PlotPanel& panel, const std::vector<double>& x,
                   const std::vector<double>& y, const cv::Scalar& colour, int thickness,
                   bool dashed) {
  if (x.size() != y.size()) {
    throw std::invalid_argument("draw_polyline: x and y differ in length");
  }
  double phase = 0.0;
  size_t drawn = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    if (!finite_point(x[i], y[i])) continue;
    ++drawn;
    if (i == 0 || !finite_point(x[i - 1], y[i - 1])) {
      phase = 0.0;
      continue;
    }
    const cv::Point a = panel.to_pixel(x[i - 1], y[i - 1]), b = panel.to_pixel(x[i], y[i]);
    if (dashed) {
      phase = dashed_segment(canvas, a, b, colour, thickness, phase);
    } else {
      cv::line(canvas, a, b, colour, thickness, cv::LINE_AA);
    }
  }
  if (drawn == 1) {
    for (size_t i = 0; i < x.size(); ++i) {
      if (finite_point(x[i], y[i])) draw_marker(canvas, panel, x[i], y[i], colour, thickness + 2);
    }
  }
}

void draw_marker(cv::Mat& canvas, const PlotPanel& panel, double x, double y,
                 const cv::Scalar& colour, int radius) {
  if (!finite_point(x, y)) return;
  cv::circle(canvas, panel.to_pixel(x, y), radius, colour, cv::FILLED, cv::LINE_AA);
}

void draw_error_bar(cv::Mat& canvas, const PlotPanel& panel, double x, double low, double high,
                    const cv::Scalar& colour, int cap_half_width) {
  if (!std::isfinite(x) || !std::isfinite(low) || !std::isfinite(high)) return;
  const cv::Point bottom = panel.to_pixel(x, low), top = panel.to_pixel(x, high);
  cv::line(canvas, bottom, top, colour, 1, cv::LINE_AA);
  for (const cv::Point& end : {bottom, top}) {
    cv::line(canvas, {end.x - cap_half_width, end.y}, {end.x + cap_half_width, end.y}, colour, 1,
             cv::LINE_AA);
  }
}

void draw_horizontal_grid(cv::Mat& canvas, const PlotPanel& panel, const std::vector<double>& ys) {
  for (double y : ys) {
    // The frame draws and labels the ends.
    if (!std::isfinite(y) || y <= panel.y_min || y >= panel.y_max) continue;
    const int row = panel.to_pixel(panel.x_min, y).y;
    cv::line(canvas, {panel.pixels.x + 1, row}, {panel.pixels.x + panel.pixels.width - 1, row},
             kPlotLightGrey, 1);
    const std::string label = tick_label(y);
    put_text(canvas, label, {panel.pixels.x - 6 - text_width(label), row + 4});
  }
}

void draw_x_tick_labels(cv::Mat& canvas, const PlotPanel& panel,
                        const std::vector<std::pair<double, std::string>>& ticks) {
  int previous_right = -1000000;
  bool lowered = false;
  const int axis_y = panel.pixels.y + panel.pixels.height;
  for (const auto& [x, label] : ticks) {
    if (!std::isfinite(x)) continue;
    const int column = panel.to_pixel(x, panel.y_min).x;
    const int width = text_width(label);
    const int left = column - width / 2;
    lowered = left < previous_right + 6 && !lowered;
    cv::line(canvas, {column, axis_y}, {column, axis_y + 4}, kPlotBlack);
    put_text(canvas, label, {left, axis_y + (lowered ? 30 : 16)});
    if (!lowered) previous_right = left + width;
  }
}

namespace {

constexpr int kLegendSample = 24, kLegendSpacing = 16;

int legend_entry_width(const LegendEntry& entry) {
  return kLegendSample + 6 + text_width(entry.label) + kLegendSpacing;
}

}  // namespace

int legend_rows(const std::vector<LegendEntry>& entries, int max_width) {
  int rows = 0, x = 0;
  for (const auto& entry : entries) {
    const int width = legend_entry_width(entry);
    if (rows == 0 || (x > 0 && x + width > max_width)) {
      ++rows;
      x = 0;
    }
    x += width;
  }
  return rows;
}

int draw_legend(cv::Mat& canvas, cv::Point origin, const std::vector<LegendEntry>& entries,
                int max_width) {
  constexpr int kSample = kLegendSample;
  cv::Point at = origin;
  for (const auto& entry : entries) {
    const int width = legend_entry_width(entry);
    if (at.x > origin.x && at.x + width > origin.x + max_width) {
      at = {origin.x, at.y + kLegendRowHeight};
    }
    const cv::Point a(at.x, at.y - 4), b(at.x + kSample, at.y - 4);
    if (entry.dashed) {
      dashed_segment(canvas, a, b, entry.colour, entry.thickness, 0.0);
    } else {
      cv::line(canvas, a, b, entry.colour, entry.thickness, cv::LINE_AA);
    }
    put_text(canvas, entry.label, {at.x + kSample + 6, at.y});
    at.x += width;
  }
  return at.y;
}

}  // namespace corrmp
