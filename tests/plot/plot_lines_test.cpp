// Tests of drawing data on a panel: solid and dashed lines, breaks at
// non-finite points, lone points, error bars, grid lines and legends.
#include "plot/plot_lines.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace corrmp {
namespace {

const cv::Scalar kRed(0, 0, 255);

// How many pixels of row `y` between columns [x0, x1) are not white.
int inked(const cv::Mat& canvas, int y, int x0, int x1) {
  int count = 0;
  for (int x = x0; x < x1; ++x) count += canvas.at<cv::Vec3b>(y, x) != cv::Vec3b(255, 255, 255);
  return count;
}

// Red, allowing for anti-aliasing.
bool reddish(const cv::Vec3b& p) { return p[2] > 200 && p[0] < 128 && p[1] < 128; }

struct Blank {
  cv::Mat canvas{100, 200, CV_8UC3, kPlotWhite};
  PlotPanel panel{cv::Rect(0, 0, 200, 100), 0.0, 10.0, 0.0, 10.0};
};

TEST(PlotLines, SolidLinesAreUnbrokenAndDashedOnesHaveGaps) {
  Blank solid, dashed;
  draw_polyline(solid.canvas, solid.panel, {1.0, 9.0}, {5.0, 5.0}, kRed);
  draw_polyline(dashed.canvas, dashed.panel, {1.0, 9.0}, {5.0, 5.0}, kRed, 1, true);
  // y = 5 is row 50; x from 1 to 9 is columns 20 to 180.
  EXPECT_EQ(inked(solid.canvas, 50, 22, 178), 156);
  const int dashes = inked(dashed.canvas, 50, 22, 178);
  EXPECT_GT(dashes, 60);
  EXPECT_LT(dashes, 130);
  EXPECT_EQ(inked(solid.canvas, 20, 0, 200), 0);  // nothing elsewhere
}

TEST(PlotLines, NonFinitePointsBreakTheLineAndLonePointsShowAsDots) {
  Blank blank;
  const double nan = std::nan("");
  draw_polyline(blank.canvas, blank.panel, {1.0, 4.0, nan, 6.0, 9.0}, {5.0, 5.0, 5.0, 5.0, 5.0},
                kRed);
  EXPECT_GT(inked(blank.canvas, 50, 25, 75), 40);    // 1 to 4
  EXPECT_EQ(inked(blank.canvas, 50, 85, 115), 0);    // the gap from 4 to 6
  EXPECT_GT(inked(blank.canvas, 50, 125, 175), 40);  // 6 to 9

  Blank lone;
  draw_polyline(lone.canvas, lone.panel, {nan, 5.0}, {1.0, 5.0}, kRed, 1);
  EXPECT_TRUE(reddish(lone.canvas.at<cv::Vec3b>(50, 100)));
  EXPECT_THROW(draw_polyline(lone.canvas, lone.panel, {1.0}, {1.0, 2.0}, kRed),
               std::invalid_argument);
}

TEST(PlotLines, ErrorBarsSpanTheirIntervalAndSkipMissingEnds) {
  Blank blank;
  draw_error_bar(blank.canvas, blank.panel, 5.0, 2.0, 8.0, kRed);
  // x = 5 is column 100; y from 2 to 8 is rows 80 to 20.
  EXPECT_TRUE(reddish(blank.canvas.at<cv::Vec3b>(50, 100)));
  EXPECT_TRUE(reddish(blank.canvas.at<cv::Vec3b>(20, 104)));  // the cap
  EXPECT_EQ(blank.canvas.at<cv::Vec3b>(10, 100), cv::Vec3b(255, 255, 255));
  Blank none;
  draw_error_bar(none.canvas, none.panel, 5.0, std::nan(""), 8.0, kRed);
  EXPECT_EQ(cv::countNonZero(none.canvas.reshape(1) != 255), 0);
}

TEST(PlotLines, GridLinesAreDrawnInsideTheRangeOnly) {
  cv::Mat canvas(120, 260, CV_8UC3, kPlotWhite);
  const PlotPanel panel{cv::Rect(60, 10, 200, 100), 0.0, 1.0, 0.0, 100.0};
  draw_horizontal_grid(canvas, panel, {0.0, 50.0, 100.0, 150.0});
  EXPECT_EQ(canvas.at<cv::Vec3b>(60, 160), cv::Vec3b(200, 200, 200));  // y = 50
  EXPECT_GT(inked(canvas, 58, 0, 60), 0);                              // its label
  EXPECT_EQ(inked(canvas, 110, 61, 259), 0);                           // y = 0: the frame's
}

TEST(PlotLines, LegendsWrapAtTheirWidth) {
  cv::Mat canvas(100, 400, CV_8UC3, kPlotWhite);
  const std::vector<LegendEntry> entries{
      {"first", kRed}, {"second", kRed, 2, true}, {"third", kRed}};
  EXPECT_EQ(draw_legend(canvas, {10, 20}, entries, 380), 20);  // one row
  EXPECT_EQ(draw_legend(canvas, {10, 50}, entries, 100), 86);  // one row each
  EXPECT_GT(text_width("second"), text_width("first"));
  EXPECT_NE(series_colour(0), series_colour(1));
  EXPECT_EQ(series_colour(0), series_colour(10));
}

}  // namespace
}  // namespace corrmp
