// Tests of the drawing helpers: data-to-pixel mapping, ranges, labels and
// PNG errors.
#include "plot/plot_canvas.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <stdexcept>

namespace corrmp {
namespace {

using ::testing::StartsWith;
using ::testing::ThrowsMessage;

TEST(PlotCanvas, PanelsMapDataToPixelsWithYUp) {
  const PlotPanel panel{cv::Rect(10, 20, 100, 50), -1.0, 1.0, 0.0, 5.0};
  EXPECT_EQ(panel.to_pixel(-1.0, 0.0), cv::Point(10, 70));  // bottom left
  EXPECT_EQ(panel.to_pixel(1.0, 5.0), cv::Point(110, 20));  // top right
  EXPECT_EQ(panel.to_pixel(0.0, 2.5), cv::Point(60, 45));
}

TEST(PlotCanvas, PlotAreasLeaveTheLabelMargins) {
  EXPECT_EQ(plot_area_in(cv::Rect(100, 30, 300, 220)), cv::Rect(152, 54, 236, 156));
}

TEST(PlotCanvas, RangesAreNeverEmptyAndLabelsShort) {
  EXPECT_EQ(padded_range(1.0, 2.0), std::make_pair(1.0, 2.0));
  const auto [lo, hi] = padded_range(3.0, 3.0);
  EXPECT_LT(lo, 3.0);
  EXPECT_GT(hi, 3.0);
  EXPECT_EQ(tick_label(0.123456), "0.123");
  EXPECT_EQ(tick_label(-2500.0), "-2.5e+03");
}

TEST(PlotCanvas, FramesAreDrawnAndUnwritablePathsNamed) {
  cv::Mat canvas(120, 200, CV_8UC3, kPlotWhite);
  const PlotPanel panel{cv::Rect(60, 30, 100, 50), 0.0, 1.0, 0.0, 1.0};
  panel.draw_frame(canvas, "t", "x");
  EXPECT_EQ(canvas.at<cv::Vec3b>(30, 110), cv::Vec3b(0, 0, 0));        // top edge
  EXPECT_EQ(canvas.at<cv::Vec3b>(55, 110), cv::Vec3b(255, 255, 255));  // inside
  EXPECT_THAT(
      [&] { write_png(canvas, "/nonexistent-dir/x.png", "here"); },
      ThrowsMessage<std::runtime_error>(StartsWith("here: cannot write '/nonexistent-dir/x.png'")));
}

// A title longer than its panel is drawn smaller, inside the panel's cell: nothing of it lands
// in the neighbouring cells (here, outside columns 4 to 296 of a trajectory figure's 300-pixel
// cell; at its usual size the title is 346 pixels wide).
TEST(PlotCanvas, LongTitlesAreShrunkToStayInTheirCell) {
  cv::Mat canvas(120, 400, CV_8UC3, kPlotWhite);
  const PlotPanel panel{plot_area_in(cv::Rect(0, 0, 300, 120)), 0.0, 1.0, 0.0, 1.0};
  panel.draw_frame(canvas, "19: combined -> anterior-to-posterior, FAILED", "x");
  cv::Mat ink;
  cv::inRange(canvas(cv::Rect(0, 0, 400, panel.pixels.y - 1)), cv::Scalar(0, 0, 0),
              cv::Scalar(200, 200, 200), ink);
  EXPECT_GT(cv::countNonZero(ink), 50);  // the title is there
  EXPECT_EQ(cv::countNonZero(ink.colRange(0, 4)), 0);
  EXPECT_EQ(cv::countNonZero(ink.colRange(296, 400)), 0);
}

}  // namespace
}  // namespace corrmp
