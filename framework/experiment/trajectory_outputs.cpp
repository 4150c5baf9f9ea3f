// Trajectory CSV and figure of a closed-loop evaluation (trajectory_outputs.hpp).
#include "experiment/trajectory_outputs.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "plot/plot_canvas.hpp"

namespace corrmp {

namespace {

const cv::Scalar kExpertGrey(190, 190, 190);
const cv::Scalar kFailedRed(30, 30, 200);  // BGR

cv::Scalar segment_colour(const std::string& segment) {
  if (segment == "pre") return {200, 100, 30};  // blue
  if (segment == "cor") return {20, 130, 240};  // orange
  if (segment == "post") return {40, 160, 40};  // green
  return {120, 60, 160};
}

void draw_path(cv::Mat& canvas, const PlotPanel& panel, const Eigen::MatrixXd& path,
               const cv::Scalar& colour, int thickness) {
  if (!path.allFinite()) return;  // a failed generation; its trial is framed red
  for (Eigen::Index t = 1; t < path.rows(); ++t) {
    cv::line(canvas, panel.to_pixel(path(t - 1, 1), path(t - 1, 0)),
             panel.to_pixel(path(t, 1), path(t, 0)), colour, thickness, cv::LINE_AA);
  }
}

}  // namespace

void write_trajectory_csv(const std::vector<TrialTrajectories>& trials, const std::string& path) {
  auto out = fmt::output_file(path);
  out.print("trial,segment,step,x,y,z,expert_x,expert_y,expert_z\n");
  for (const auto& trial : trials) {
    for (const auto& [segment, generated] : trial.generated) {
      const Eigen::MatrixXd& expert = trial.expert.at(segment);
      for (Eigen::Index t = 0; t < generated.rows(); ++t) {
        out.print("{},{},{},{},{},{},{},{},{}\n", trial.trial, segment, t, generated(t, 0),
                  generated(t, 1), generated(t, 2), expert(t, 0), expert(t, 1), expert(t, 2));
      }
    }
  }
}

void write_trajectory_figure(const std::vector<TrialTrajectories>& trials,
                             const std::string& png_path) {
  constexpr const char* kWhere = "write_trajectory_figure";
  if (trials.empty()) throw std::invalid_argument(fmt::format("{}: no trials", kWhere));
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  double y_lo = x_lo, y_hi = -x_lo;
  for (const auto& trial : trials) {
    for (const auto* paths : {&trial.generated, &trial.expert}) {
      for (const auto& [segment, path] : *paths) {
        if (path.rows() == 0 || !path.allFinite()) continue;
        x_lo = std::min(x_lo, path.col(0).minCoeff());
        x_hi = std::max(x_hi, path.col(0).maxCoeff());
        y_lo = std::min(y_lo, path.col(1).minCoeff());
        y_hi = std::max(y_hi, path.col(1).maxCoeff());
      }
    }
  }
  if (!(x_hi >= x_lo)) x_lo = x_hi = y_lo = y_hi = 0.0;  // nothing finite to draw
  const auto [x_min, x_max] = padded_range(x_lo - 0.01, x_hi + 0.01);
  const auto [y_min, y_max] = padded_range(y_lo - 0.01, y_hi + 0.01);

  const int count = static_cast<int>(trials.size());
  const int columns = std::min(count, kTrajectoryColumns);
  const int rows = (count + kTrajectoryColumns - 1) / kTrajectoryColumns;
  cv::Mat canvas(kTrajectoryHeader + rows * kTrajectoryPanelHeight, columns * kTrajectoryPanelWidth,
                 CV_8UC3, kPlotWhite);
  put_text(canvas,
           "top view, x (m) up against y (m) right; grey: expert; generated pre blue, cor orange, "
           "post green",
           {8, 20}, 0.45);
  for (int i = 0; i < count; ++i) {
    const TrialTrajectories& trial = trials[i];
    const cv::Point origin((i % kTrajectoryColumns) * kTrajectoryPanelWidth,
                           kTrajectoryHeader + (i / kTrajectoryColumns) * kTrajectoryPanelHeight);
    const PlotPanel panel{
        plot_area_in({origin.x, origin.y, kTrajectoryPanelWidth, kTrajectoryPanelHeight}), y_min,
        y_max, x_min, x_max};
    const std::string chosen = trial.chosen_action.empty() ? "?" : trial.chosen_action;
    const std::string expected = trial.expected_action.empty() ? "?" : trial.expected_action;
    panel.draw_frame(canvas,
                     fmt::format("{}: {} -> {}, {}", trial.trial, expected, chosen,
                                 trial.success ? "ok" : "FAILED"),
                     "y (m)");
    if (!trial.success) cv::rectangle(canvas, panel.pixels, kFailedRed, 2);
    for (const auto& [segment, path] : trial.expert) draw_path(canvas, panel, path, kExpertGrey, 3);
    for (const auto& [segment, path] : trial.generated) {
      draw_path(canvas, panel, path, segment_colour(segment), 1);
    }
  }
  write_png(canvas, png_path, kWhere);
}

}  // namespace corrmp
