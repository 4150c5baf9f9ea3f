// A figure of line panels under a heading and a legend: the reproduction
// report's trajectory comparisons (paper, Fig. "Comparison of ground-truth,
// prediction, and robot execution") and training curves (docs/sweeps.md).
// Each panel takes its axis ranges from its own finite data unless given.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "plot/plot_lines.hpp"

namespace corrmp {

struct PlotLine {
  std::vector<double> x, y;
  cv::Scalar colour = kPlotBlack;
  int thickness = 1;
  bool dashed = false;
};

struct LinePanel {
  std::string title, x_label;
  std::vector<PlotLine> lines;
  std::optional<std::pair<double, double>> x_range, y_range;  // else from the data
  std::string empty_text = "no data";  // written in a panel with nothing finite to draw
};

struct LineFigure {
  std::string heading;
  std::vector<LegendEntry> legend;
  std::vector<LinePanel> panels;  // row by row
  int columns = 3;
  int panel_width = 320, panel_height = 240;
};

// The heading and legend take kLineFigureHeader pixels above the panels with
// a legend of one row (or none), kLegendRowHeight more for each further row.
constexpr int kLineFigureHeader = 60;
int line_figure_header(const LineFigure& figure);

// columns x panel_width wide (fewer columns with fewer panels),
// line_figure_header + rows x panel_height high. Throws
// std::invalid_argument without panels or with columns or panel sizes below 1.
cv::Mat draw_line_figure(const LineFigure& figure);

// The size draw_line_figure gives `figure`.
cv::Size line_figure_size(const LineFigure& figure);

}  // namespace corrmp
