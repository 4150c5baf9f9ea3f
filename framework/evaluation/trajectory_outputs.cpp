// Trajectory CSV and figure of a closed-loop evaluation (trajectory_outputs.hpp).
#include "evaluation/trajectory_outputs.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "plot/plot_canvas.hpp"
#include "plot/plot_lines.hpp"

namespace corrmp {

namespace {

const cv::Scalar kExpertGrey(190, 190, 190);
const cv::Scalar kFailedRed(30, 30, 200);  // BGR
constexpr double kExecutedShade = 0.45;    // of the segment's colour

// The segments' colours in execution order: blue, orange, green, purple, brown.
struct SegmentColour {
  cv::Scalar bgr;
  const char* name;
};
const SegmentColour kSegmentColours[] = {{{200, 100, 30}, "blue"},
                                         {{20, 130, 240}, "orange"},
                                         {{40, 160, 40}, "green"},
                                         {{160, 60, 120}, "purple"},
                                         {{30, 80, 140}, "brown"}};

SegmentColour segment_colour(const std::vector<std::string>& order, const std::string& segment) {
  const auto it = std::find(order.begin(), order.end(), segment);
  const size_t index = static_cast<size_t>(it - order.begin());
  constexpr size_t kCount = sizeof(kSegmentColours) / sizeof(kSegmentColours[0]);
  return index < order.size() ? kSegmentColours[index % kCount]
                              : SegmentColour{{90, 90, 90}, "grey"};
}

// A segment's rows in world coordinates: a relative segment's offsets are
// added to its origin.
Eigen::MatrixXd in_world(const EvaluatedTrial& trial, const TaskReport& task,
                         const std::string& segment, const Eigen::MatrixXd& path) {
  const auto origin = trial.origins.find(segment);
  if (origin == trial.origins.end()) return path;
  Eigen::MatrixXd world = path;
  for (int c : relative_columns_of(task, path.cols())) world.col(c).array() += origin->second(c);
  return world;
}

void draw_path(cv::Mat& canvas, const PlotPanel& panel, const TaskReport& task,
               const Eigen::MatrixXd& path, const cv::Scalar& colour, int thickness) {
  if (!path.allFinite()) return;  // a failed generation; its trial is framed red
  const int h = task.plot_horizontal, v = task.plot_vertical;
  for (Eigen::Index t = 1; t < path.rows(); ++t) {
    cv::line(canvas, panel.to_pixel(path(t - 1, h), path(t - 1, v)),
             panel.to_pixel(path(t, h), path(t, v)), colour, thickness, cv::LINE_AA);
  }
}

// Dashed over the generated path, in the segment's colour darkened: where the
// execution follows the command, the generated line shows between the dashes.
void draw_executed(cv::Mat& canvas, const PlotPanel& panel, const TaskReport& task,
                   const Eigen::MatrixXd& path, const cv::Scalar& segment_bgr) {
  const int h = task.plot_horizontal, v = task.plot_vertical;
  const std::vector<double> x(path.col(h).data(), path.col(h).data() + path.rows());
  const std::vector<double> y(path.col(v).data(), path.col(v).data() + path.rows());
  draw_polyline(canvas, panel, x, y, segment_bgr * kExecutedShade, 1, true);
}

}  // namespace

void write_trajectory_csv(const std::vector<EvaluatedTrial>& trials, const TaskReport& task,
                          const std::string& path) {
  auto out = fmt::output_file(path);
  const auto& columns = task.trajectory_columns;
  out.print("trial,segment,step");
  for (const auto& c : columns) out.print(",{}", c);
  for (const auto& c : columns) out.print(",expert_{}", c);
  for (const auto& c : columns) out.print(",executed_{}", c);
  out.print("\n");
  const auto width = static_cast<Eigen::Index>(columns.size());
  for (const auto& trial : trials) {
    for (const auto& [segment, relative] : trial.generated) {
      const Eigen::MatrixXd& expert_relative = trial.expert.at(segment);
      if (relative.cols() != width || expert_relative.cols() != width) {
        throw std::invalid_argument(fmt::format(
            "write_trajectory_csv: trial {} segment '{}' has {} columns, the task declares {}",
            trial.trial, segment, relative.cols(), width));
      }
      const auto executed_relative = trial.executed.find(segment);
      if (executed_relative != trial.executed.end() && executed_relative->second.cols() != width) {
        throw std::invalid_argument(fmt::format(
            "write_trajectory_csv: trial {} segment '{}' has {} executed columns, the task "
            "declares {}",
            trial.trial, segment, executed_relative->second.cols(), width));
      }
      const Eigen::MatrixXd generated = in_world(trial, task, segment, relative);
      const Eigen::MatrixXd expert = in_world(trial, task, segment, expert_relative);
      const Eigen::MatrixXd executed =
          executed_relative == trial.executed.end()
              ? Eigen::MatrixXd(0, width)
              : in_world(trial, task, segment, executed_relative->second);
      for (Eigen::Index t = 0; t < generated.rows(); ++t) {
        out.print("{},{},{}", trial.trial, segment, t);
        for (Eigen::Index c = 0; c < width; ++c) out.print(",{}", generated(t, c));
        for (Eigen::Index c = 0; c < width; ++c) out.print(",{}", expert(t, c));
        for (Eigen::Index c = 0; c < width; ++c) {
          if (t < executed.rows()) {
            out.print(",{}", executed(t, c));
          } else {
            out.print(",");
          }
        }
        out.print("\n");
      }
    }
  }
}

void write_trajectory_figure(const std::vector<EvaluatedTrial>& trials, const TaskReport& task,
                             const std::vector<std::string>& segment_order,
                             const std::string& png_path) {
  constexpr const char* kWhere = "write_trajectory_figure";
  if (trials.empty()) throw std::invalid_argument(fmt::format("{}: no trials", kWhere));
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  double y_lo = x_lo, y_hi = -x_lo;
  const int h = task.plot_horizontal, v = task.plot_vertical;
  const int width = static_cast<int>(task.trajectory_columns.size());
  if (h < 0 || v < 0 || h >= width || v >= width) {
    throw std::invalid_argument(
        fmt::format("{}: plot columns {} and {} of a {}-column trajectory", kWhere, h, v, width));
  }
  for (const auto& trial : trials) {
    for (const auto* paths : {&trial.generated, &trial.expert, &trial.executed}) {
      for (const auto& [segment, relative_path] : *paths) {
        const Eigen::MatrixXd path = in_world(trial, task, segment, relative_path);
        if (path.rows() == 0 || !path.allFinite() || path.cols() != width) continue;
        x_lo = std::min(x_lo, path.col(v).minCoeff());
        x_hi = std::max(x_hi, path.col(v).maxCoeff());
        y_lo = std::min(y_lo, path.col(h).minCoeff());
        y_hi = std::max(y_hi, path.col(h).maxCoeff());
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
  const std::string& vertical = task.trajectory_columns[v];
  const std::string& horizontal = task.trajectory_columns[h];
  std::string legend;
  for (const auto& segment : segment_order) {
    legend += fmt::format("{}{} {}", legend.empty() ? "" : ", ", segment,
                          segment_colour(segment_order, segment).name);
  }
  const bool executed = std::any_of(trials.begin(), trials.end(),
                                    [](const EvaluatedTrial& t) { return !t.executed.empty(); });
  put_text(canvas,
           fmt::format("{} up against {} right; grey: expert; generated {}{}", vertical, horizontal,
                       legend, executed ? "; dashed: executed" : ""),
           {8, 20}, 0.45);
  for (int i = 0; i < count; ++i) {
    const EvaluatedTrial& trial = trials[i];
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
                     horizontal);
    if (!trial.success) cv::rectangle(canvas, panel.pixels, kFailedRed, 2);
    for (const auto& [segment, path] : trial.expert) {
      if (path.cols() == width) {
        draw_path(canvas, panel, task, in_world(trial, task, segment, path), kExpertGrey, 3);
      }
    }
    for (const auto& [segment, path] : trial.generated) {
      if (path.cols() == width) {
        draw_path(canvas, panel, task, in_world(trial, task, segment, path),
                  segment_colour(segment_order, segment).bgr, 1);
      }
    }
    for (const auto& [segment, path] : trial.executed) {
      if (path.cols() == width) {
        draw_executed(canvas, panel, task, in_world(trial, task, segment, path),
                      segment_colour(segment_order, segment).bgr);
      }
    }
  }
  write_png(canvas, png_path, kWhere);
}

}  // namespace corrmp
