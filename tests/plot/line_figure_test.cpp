// Tests of the line-panel figure: its size, ranges, empty panels and clipping.
#include "plot/line_figure.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace corrmp {
namespace {

LinePanel line_panel(double x0, double x1) {
  LinePanel panel;
  panel.title = "t";
  panel.x_label = "x";
  panel.lines.push_back({{x0, x1}, {0.0, 1.0}, cv::Scalar(0, 0, 255), 1, false});
  return panel;
}

TEST(LineFigure, IsSizedByItsColumnsAndRows) {
  LineFigure figure;
  figure.columns = 2;
  figure.panel_width = 200;
  figure.panel_height = 150;
  figure.panels = {line_panel(0, 1), line_panel(0, 2), line_panel(1, 2)};
  const cv::Mat canvas = draw_line_figure(figure);
  EXPECT_EQ(canvas.size(), cv::Size(400, kLineFigureHeader + 300));
  EXPECT_EQ(line_figure_size(figure), canvas.size());
  figure.panels.resize(1);
  EXPECT_EQ(draw_line_figure(figure).size(), cv::Size(200, kLineFigureHeader + 150));
  figure.panels.clear();
  EXPECT_THROW(draw_line_figure(figure), std::invalid_argument);
}

TEST(LineFigure, LinesOutsideAGivenRangeStayInTheirPanel) {
  LineFigure figure;
  figure.columns = 1;
  figure.panel_width = 300;
  figure.panel_height = 200;
  LinePanel panel = line_panel(-10.0, 10.0);  // far outside [0, 1]
  panel.x_range = std::make_pair(0.0, 1.0);
  panel.y_range = std::make_pair(0.0, 1.0);
  figure.panels = {panel};
  const cv::Mat canvas = draw_line_figure(figure);
  const cv::Rect area = plot_area_in({0, kLineFigureHeader, 300, 200});
  int red_outside = 0;
  for (int y = 0; y < canvas.rows; ++y) {
    for (int x = 0; x < canvas.cols; ++x) {
      const bool inside = area.contains({x, y});
      if (!inside && canvas.at<cv::Vec3b>(y, x) == cv::Vec3b(0, 0, 255)) ++red_outside;
    }
  }
  EXPECT_EQ(red_outside, 0);
}

TEST(LineFigure, PanelsWithoutDataSaySo) {
  LineFigure figure;
  figure.columns = 1;
  LinePanel empty;
  empty.title = "nothing";
  empty.lines.push_back({{std::nan("")}, {1.0}, cv::Scalar(0, 0, 255), 1, false});
  figure.panels = {empty};
  const cv::Mat canvas = draw_line_figure(figure);
  const cv::Rect area = plot_area_in({0, kLineFigureHeader, 320, 240});
  const cv::Mat inside = canvas(area + cv::Point(2, 2) - cv::Size(4, 4));
  // The grey "no data" text and nothing red.
  int grey = 0, red = 0;
  for (int y = 0; y < inside.rows; ++y) {
    for (int x = 0; x < inside.cols; ++x) {
      const cv::Vec3b p = inside.at<cv::Vec3b>(y, x);
      grey += p[0] == p[1] && p[1] == p[2] && p[0] < 200;
      red += p == cv::Vec3b(0, 0, 255);
    }
  }
  EXPECT_GT(grey, 0);
  EXPECT_EQ(red, 0);
}

}  // namespace
}  // namespace corrmp
