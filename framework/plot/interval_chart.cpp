// A chart of means with their intervals (interval_chart.hpp).
#include "plot/interval_chart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "plot/plot_canvas.hpp"
#include "plot/plot_lines.hpp"

namespace corrmp {

namespace {

constexpr int kLeft = 70, kRight = 20, kTop = 60, kBottom = 80;

std::pair<double, double> x_range(const IntervalChart& chart) {
  if (!chart.categories.empty()) {
    return {-0.5, static_cast<double>(chart.categories.size()) - 0.5};
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& series : chart.series) {
    for (const auto& point : series.points) {
      if (!std::isfinite(point.x)) continue;
      lo = std::min(lo, point.x);
      hi = std::max(hi, point.x);
    }
  }
  if (!(hi >= lo)) return {0.0, 1.0};
  const double margin = hi > lo ? 0.06 * (hi - lo) : 0.0;
  return padded_range(lo - margin, hi + margin);
}

// The numeric axis' ticks: every distinct x of the points, in full.
std::vector<std::pair<double, std::string>> numeric_ticks(const IntervalChart& chart) {
  std::vector<double> xs;
  for (const auto& series : chart.series) {
    for (const auto& point : series.points) {
      if (std::isfinite(point.x)) xs.push_back(point.x);
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::vector<std::pair<double, std::string>> ticks;
  for (double x : xs) ticks.emplace_back(x, fmt::format("{}", x));  // 20000, not 2e+04
  return ticks;
}

}  // namespace

cv::Mat draw_interval_chart(const IntervalChart& chart) {
  if (!(chart.y_max > chart.y_min)) {
    throw std::invalid_argument("draw_interval_chart: y_max must exceed y_min");
  }
  cv::Mat canvas(kIntervalChartHeight, kIntervalChartWidth, CV_8UC3, kPlotWhite);
  const bool categorical = !chart.categories.empty();
  put_text(canvas, chart.title, {8, 20}, 0.5);
  // The legend (two or more series) goes first: the plot starts below it.
  int top = kTop;
  if (chart.series.size() > 1) {
    std::vector<LegendEntry> entries;
    for (size_t s = 0; s < chart.series.size(); ++s) {
      entries.push_back({chart.series[s].name, series_colour(s), 2, false});
    }
    top = draw_legend(canvas, {12, kTop - 20}, entries, kIntervalChartWidth - 24) + 32;
    top = std::min(top, kIntervalChartHeight - kBottom - 120);  // a long legend overlaps
  }
  const auto [x_min, x_max] = x_range(chart);
  const PlotPanel panel{
      {kLeft, top, kIntervalChartWidth - kLeft - kRight, kIntervalChartHeight - top - kBottom},
      x_min,
      x_max,
      chart.y_min,
      chart.y_max};
  draw_horizontal_grid(canvas, panel, chart.y_grid);
  panel.draw_frame(canvas, "", "", false);
  put_text(canvas, chart.y_label, {8, top - 10});
  put_text(canvas, chart.x_label,
           {panel.pixels.x + panel.pixels.width / 2 - text_width(chart.x_label) / 2,
            kIntervalChartHeight - 12},
           0.45);
  std::vector<std::pair<double, std::string>> ticks;
  if (categorical) {
    for (size_t i = 0; i < chart.categories.size(); ++i) {
      ticks.emplace_back(static_cast<double>(i), chart.categories[i]);
    }
  } else {
    ticks = numeric_ticks(chart);
  }
  draw_x_tick_labels(canvas, panel, ticks);

  // Side by side on a categorical axis: a series' offset within its category.
  const double spread = categorical ? 0.5 : 0.0;
  const size_t count = chart.series.size();
  for (size_t s = 0; s < count; ++s) {
    const IntervalSeries& series = chart.series[s];
    const cv::Scalar colour = series_colour(s);
    const double offset =
        count > 1 ? spread * (static_cast<double>(s) / static_cast<double>(count - 1) - 0.5) : 0.0;
    std::vector<double> xs, means;
    for (const auto& point : series.points) {
      xs.push_back(point.x + offset);
      means.push_back(point.mean);
    }
    if (!categorical) draw_polyline(canvas, panel, xs, means, colour, 2);
    for (size_t i = 0; i < xs.size(); ++i) {
      const IntervalPoint& point = series.points[i];
      draw_error_bar(canvas, panel, xs[i], point.low, point.high, colour);
      draw_marker(canvas, panel, xs[i], point.mean, colour, 4);
    }
  }
  return canvas;
}

}  // namespace corrmp
