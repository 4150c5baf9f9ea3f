// Drawing data on a PlotPanel (plot_canvas.hpp) for the reproduction report's
// figures (docs/sweeps.md, "Comparing and reporting"): polylines, solid or
// dashed, that break at non-finite points; point markers; vertical error bars
// for intervals; tick labels at chosen x positions; horizontal grid lines; a
// legend row; and a palette for series.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "plot/plot_canvas.hpp"

namespace corrmp {

// The i-th colour (BGR) of a ten-colour palette, repeating.
cv::Scalar series_colour(size_t index);

// The width in pixels of `text` as put_text draws it at `scale`.
int text_width(const std::string& text, double scale = 0.4);

// Connects consecutive finite points (x[i], y[i]); a non-finite value breaks
// the line. A lone finite point is drawn as a dot, so one-point series show.
// Throws std::invalid_argument when x and y differ in length.
void draw_polyline(cv::Mat& canvas, const PlotPanel& panel, const std::vector<double>& x,
                   const std::vector<double>& y, const cv::Scalar& colour, int thickness = 1,
                   bool dashed = false);

void draw_marker(cv::Mat& canvas, const PlotPanel& panel, double x, double y,
                 const cv::Scalar& colour, int radius = 3);

// A vertical bar from (x, low) to (x, high) with short caps; nothing when
// either end is not finite.
void draw_error_bar(cv::Mat& canvas, const PlotPanel& panel, double x, double low, double high,
                    const cv::Scalar& colour, int cap_half_width = 5);

// Light grey horizontal lines at the given y values strictly inside the
// panel's range, labelled on the left (draw_frame labels the ends).
void draw_horizontal_grid(cv::Mat& canvas, const PlotPanel& panel, const std::vector<double>& ys);

// Labels centred under the x axis at the given x positions; a label that would
// overlap its left neighbour goes one line lower.
void draw_x_tick_labels(cv::Mat& canvas, const PlotPanel& panel,
                        const std::vector<std::pair<double, std::string>>& ticks);

struct LegendEntry {
  std::string label;
  cv::Scalar colour;
  int thickness = 2;
  bool dashed = false;
};

// The entries left to right from `origin` (the baseline of their text), each
// a short line sample and its label, wrapping at `max_width` pixels; returns
// the baseline y of the last row.
int draw_legend(cv::Mat& canvas, cv::Point origin, const std::vector<LegendEntry>& entries,
                int max_width);

// The rows draw_legend takes for the entries (0 without entries); rows are
// kLegendRowHeight pixels apart.
constexpr int kLegendRowHeight = 18;
int legend_rows(const std::vector<LegendEntry>& entries, int max_width);

}  // namespace corrmp
