// Tests of the interval chart: its size, its points and bars, and its checks.
#include "plot/interval_chart.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "plot/plot_lines.hpp"

namespace corrmp {
namespace {

int pixels_of(const cv::Mat& canvas, const cv::Scalar& colour) {
  const cv::Vec3b bgr(static_cast<uchar>(colour[0]), static_cast<uchar>(colour[1]),
                      static_cast<uchar>(colour[2]));
  int count = 0;
  for (int y = 0; y < canvas.rows; ++y) {
    for (int x = 0; x < canvas.cols; ++x) count += canvas.at<cv::Vec3b>(y, x) == bgr;
  }
  return count;
}

TEST(IntervalChart, DrawsEachSeriesInItsColourAtAFixedSize) {
  IntervalChart chart;
  chart.title = "success";
  chart.y_min = 0.0;
  chart.y_max = 100.0;
  chart.series = {{"a", {{1.0, 50.0, 30.0, 70.0}, {2.0, 60.0, 40.0, 80.0}}},
                  {"b", {{1.0, 20.0, std::nan(""), std::nan("")}}}};
  const cv::Mat canvas = draw_interval_chart(chart);
  EXPECT_EQ(canvas.size(), cv::Size(kIntervalChartWidth, kIntervalChartHeight));
  EXPECT_GT(pixels_of(canvas, series_colour(0)), 50);  // a line, two dots and bars
  EXPECT_GT(pixels_of(canvas, series_colour(1)), 10);  // a dot (and a legend sample)
}

TEST(IntervalChart, CategoricalAxesNeedNoNumbersAndEmptyRangesAreRefused) {
  IntervalChart chart;
  chart.categories = {"corridor_pc", "corridor_ae", "corridor_mono"};
  chart.series = {{"", {{0.0, 0.9, 0.8, 1.0}, {2.0, 0.5, 0.2, 0.8}}}};
  EXPECT_EQ(draw_interval_chart(chart).size(), cv::Size(kIntervalChartWidth, kIntervalChartHeight));
  chart.y_max = chart.y_min;
  EXPECT_THROW(draw_interval_chart(chart), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
