// The knotting figure (rope_knot_figure.hpp).
#include "envs/rope_knot/rope_knot_figure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "plot/plot_canvas.hpp"

namespace corrmp {

namespace {

constexpr int kPanel = 420;
constexpr int kLegend = 70;
const cv::Scalar kSuccessGreen(40, 160, 40);  // BGR

cv::Scalar failure_colour(const std::string& failure) {
  if (failure.rfind("missed enclose", 0) == 0) return {40, 40, 220};  // red
  if (failure.rfind("near miss", 0) == 0) return {0, 190, 240};       // yellow
  if (failure.rfind("knot lost", 0) == 0) return {170, 60, 160};      // purple
  return {60, 60, 60};                                                // physics faults
}

cv::Scalar trial_colour(const EvaluatedTrial& trial) {
  return trial.success ? kSuccessGreen : failure_colour(trial.failure);
}

// Points (y, x) in cm of a trajectory's first two columns.
std::vector<cv::Point2d> top_view(const Eigen::MatrixXd& path) {
  std::vector<cv::Point2d> points;
  if (path.cols() < 2 || !path.allFinite()) return points;
  for (Eigen::Index t = 0; t < path.rows(); ++t) {
    points.emplace_back(100.0 * path(t, 1), 100.0 * path(t, 0));
  }
  return points;
}

struct Bounds {
  double lo_x = std::numeric_limits<double>::infinity(), hi_x = -lo_x, lo_y = lo_x, hi_y = -lo_x;
  void add(const cv::Point2d& p) {
    lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
  }
  PlotPanel panel(const cv::Rect& cell) const {
    const bool empty = !(hi_x >= lo_x);
    const auto [x0, x1] = padded_range(empty ? -1 : lo_x - 0.5, empty ? 1 : hi_x + 0.5);
    const auto [y0, y1] = padded_range(empty ? -1 : lo_y - 0.5, empty ? 1 : hi_y + 0.5);
    return PlotPanel{plot_area_in(cell), x0, x1, y0, y1};
  }
};

void draw_polyline(cv::Mat& canvas, const PlotPanel& panel, const std::vector<cv::Point2d>& points,
                   const cv::Scalar& colour, int thickness) {
  for (size_t i = 1; i < points.size(); ++i) {
    cv::line(canvas, panel.to_pixel(points[i - 1].x, points[i - 1].y),
             panel.to_pixel(points[i].x, points[i].y), colour, thickness, cv::LINE_AA);
  }
}

void draw_dot(cv::Mat& canvas, const PlotPanel& panel, const cv::Point2d& p,
              const cv::Scalar& colour) {
  cv::circle(canvas, panel.to_pixel(p.x, p.y), 4, colour, cv::FILLED, cv::LINE_AA);
}

std::vector<cv::Point2d> demonstrated_corrections(const Demonstration& demo) {
  const SegmentTrajectory* cor = demo.find("cor");
  return cor != nullptr ? top_view(cor->y) : std::vector<cv::Point2d>{};
}

std::optional<cv::Point2d> context_point(const Eigen::VectorXd& context) {
  if (context.size() < 2 || !context.allFinite()) return std::nullopt;
  return cv::Point2d(100.0 * context(1), 100.0 * context(0));
}

}  // namespace

void write_knotting_figure(const std::vector<EvaluatedTrial>& trials,
                           const std::vector<Demonstration>& train, const std::string& png_path) {
  Bounds corrections, contexts;
  for (const auto& demo : train) {
    for (const auto& p : demonstrated_corrections(demo)) corrections.add(p);
    if (const SegmentTrajectory* cor = demo.find("cor")) {
      if (auto p = context_point(cor->context)) contexts.add(*p);
    }
  }
  for (const auto& trial : trials) {
    if (trial.generated.count("cor")) {
      for (const auto& p : top_view(trial.generated.at("cor"))) corrections.add(p);
    }
    if (trial.contexts.count("cor")) {
      if (auto p = context_point(trial.contexts.at("cor"))) contexts.add(*p);
    }
  }
  cv::Mat canvas(kPanel + kLegend, 2 * kPanel, CV_8UC3, kPlotWhite);
  const PlotPanel left = corrections.panel({0, 0, kPanel, kPanel});
  const PlotPanel right = contexts.panel({kPanel, 0, kPanel, kPanel});
  left.draw_frame(canvas, "corrections: left gripper dx (cm) up", "dy (cm)");
  right.draw_frame(canvas, "contexts: rope end - gripper, dx (cm) up", "dy (cm)");

  for (const auto& demo : train) {
    draw_polyline(canvas, left, demonstrated_corrections(demo), kPlotLightGrey, 2);
    if (const SegmentTrajectory* cor = demo.find("cor")) {
      if (auto p = context_point(cor->context)) draw_dot(canvas, right, *p, kPlotLightGrey);
    }
  }
  for (const auto& trial : trials) {
    const cv::Scalar colour = trial_colour(trial);
    if (trial.generated.count("cor")) {
      draw_polyline(canvas, left, top_view(trial.generated.at("cor")), colour, 1);
    }
    if (trial.contexts.count("cor")) {
      if (auto p = context_point(trial.contexts.at("cor"))) draw_dot(canvas, right, *p, colour);
    }
  }
  const int y = kPanel + 20;
  put_text(canvas, "grey: training demonstrations; green: knot tied", {10, y});
  put_text(canvas, "red: missed enclose", {10, y + 20}, 0.4, failure_colour("missed enclose"));
  put_text(canvas, "yellow: near miss", {200, y + 20}, 0.4, failure_colour("near miss"));
  put_text(canvas, "purple: knot lost while tightening", {330, y + 20}, 0.4,
           failure_colour("knot lost"));
  put_text(canvas, "dark grey: physics fault, invalid trajectory", {560, y + 20}, 0.4,
           failure_colour("physics"));
  write_png(canvas, png_path, "write_knotting_figure");
}

}  // namespace corrmp
