// A chart of means with their intervals (task success against a swept
// parameter, or per experiment; docs/sweeps.md, "Comparing and reporting"):
// each series a colour, its points as dots with vertical interval bars, joined
// by lines on a numeric x axis; on a categorical axis the points stand at the
// categories, series side by side, unjoined.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace corrmp {

struct IntervalPoint {
  double x = 0.0;  // the value, or the category's index on a categorical axis
  double mean = 0.0;
  double low = 0.0, high = 0.0;  // NaN: no interval (one run)
};

struct IntervalSeries {
  std::string name;
  std::vector<IntervalPoint> points;  // in increasing x
};

struct IntervalChart {
  std::string title, x_label, y_label;
  std::vector<std::string> categories;  // non-empty: a categorical x axis
  std::vector<IntervalSeries> series;
  double y_min = 0.0, y_max = 1.0;
  std::vector<double> y_grid;  // light lines at these values
};

constexpr int kIntervalChartWidth = 900;
constexpr int kIntervalChartHeight = 480;

// kIntervalChartWidth x kIntervalChartHeight; a legend names the series
// when there are two or more. Throws std::invalid_argument when y_max <= y_min.
cv::Mat draw_interval_chart(const IntervalChart& chart);

}  // namespace corrmp
