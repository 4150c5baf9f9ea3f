// A figure of line panels (line_figure.hpp).
#include "plot/line_figure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace corrmp {

namespace {

std::pair<double, double> data_range(const LinePanel& panel, bool horizontal) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& line : panel.lines) {
    for (size_t i = 0; i < line.x.size() && i < line.y.size(); ++i) {
      if (!std::isfinite(line.x[i]) || !std::isfinite(line.y[i])) continue;
      const double v = horizontal ? line.x[i] : line.y[i];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (!(hi >= lo)) return {0.0, 1.0};
  const double margin = 0.04 * (hi - lo);
  return padded_range(lo - margin, hi + margin);
}

bool has_finite_point(const LinePanel& panel) {
  for (const auto& line : panel.lines) {
    for (size_t i = 0; i < line.x.size() && i < line.y.size(); ++i) {
      if (std::isfinite(line.x[i]) && std::isfinite(line.y[i])) return true;
    }
  }
  return false;
}

}  // namespace

int line_figure_header(const LineFigure& figure) {
  const int width =
      std::min(static_cast<int>(figure.panels.size()), figure.columns) * figure.panel_width;
  const int rows = legend_rows(figure.legend, width - 16);
  return kLineFigureHeader + std::max(0, rows - 1) * kLegendRowHeight;
}

cv::Size line_figure_size(const LineFigure& figure) {
  if (figure.panels.empty() || figure.columns < 1 || figure.panel_width < 1 ||
      figure.panel_height < 1) {
    throw std::invalid_argument("draw_line_figure: no panels, or columns or panel size below 1");
  }
  const int count = static_cast<int>(figure.panels.size());
  const int columns = std::min(count, figure.columns);
  const int rows = (count + figure.columns - 1) / figure.columns;
  return {columns * figure.panel_width, line_figure_header(figure) + rows * figure.panel_height};
}

cv::Mat draw_line_figure(const LineFigure& figure) {
  const cv::Size size = line_figure_size(figure);
  const int header = line_figure_header(figure);
  cv::Mat canvas(size, CV_8UC3, kPlotWhite);
  put_text(canvas, figure.heading, {8, 20}, 0.45);
  draw_legend(canvas, {8, 42}, figure.legend, size.width - 16);
  for (size_t i = 0; i < figure.panels.size(); ++i) {
    const LinePanel& data = figure.panels[i];
    const int column = static_cast<int>(i) % figure.columns;
    const int row = static_cast<int>(i) / figure.columns;
    const cv::Rect cell(column * figure.panel_width, header + row * figure.panel_height,
                        figure.panel_width, figure.panel_height);
    const auto [x_min, x_max] = data.x_range ? *data.x_range : data_range(data, true);
    const auto [y_min, y_max] = data.y_range ? *data.y_range : data_range(data, false);
    const PlotPanel panel{plot_area_in(cell), x_min, x_max, y_min, y_max};
    panel.draw_frame(canvas, data.title, data.x_label);
    if (!has_finite_point(data)) {
      put_text(canvas, data.empty_text,
               {panel.pixels.x + 8, panel.pixels.y + panel.pixels.height / 2}, 0.45, kPlotGrey);
      continue;
    }
    cv::Mat clipped = canvas(panel.pixels);  // lines outside a given range stay in the panel
    const PlotPanel local{
        {0, 0, panel.pixels.width, panel.pixels.height}, x_min, x_max, y_min, y_max};
    for (const auto& line : data.lines) {
      draw_polyline(clipped, local, line.x, line.y, line.colour, line.thickness, line.dashed);
    }
    cv::rectangle(canvas, panel.pixels.tl(), panel.pixels.br(), kPlotBlack, 1);
  }
  return canvas;
}

}  // namespace corrmp
