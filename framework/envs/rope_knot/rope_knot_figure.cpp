// The knotting figure (rope_knot_figure.hpp).
#include "envs/rope_knot/rope_knot_figure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "core/task_declaration.hpp"
#include "plot/plot_canvas.hpp"

namespace corrmp {

namespace {

constexpr int kPanel = 420;
constexpr int kLegendLine = 20;               // px per legend line
const cv::Scalar kSuccessGreen(40, 160, 40);  // BGR
const cv::Scalar kOtherFailure(0, 0, 0);

// One colour per declared category, by its place (cycling past the last).
const std::vector<cv::Scalar>& category_palette() {
  static const std::vector<cv::Scalar> palette{
      {40, 40, 220},   // red
      {0, 190, 240},   // yellow
      {170, 60, 160},  // purple
      {90, 90, 90},    // dark grey
      {30, 90, 150},   // brown
      {200, 110, 30},  // blue
      {0, 120, 255},   // orange
      {160, 160, 0},   // teal
      {150, 80, 240},  // pink
      {40, 130, 110},  // olive
  };
  return palette;
}

// The place of the first category `failure` starts with; -1 for none.
int category_of(const std::string& failure, const std::vector<std::string>& categories) {
  for (size_t c = 0; c < categories.size(); ++c) {
    if (in_failure_category(failure, categories[c])) return static_cast<int>(c);
  }
  return -1;
}

cv::Scalar category_colour(int category) {
  if (category < 0) return kOtherFailure;
  const auto& palette = category_palette();
  return palette[static_cast<size_t>(category) % palette.size()];
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

// The legend's entries laid out left to right from `x0`, wrapping at `width`: the top-left
// of each line, one per entry.
std::vector<cv::Point> legend_layout(const std::vector<KnottingLegendEntry>& entries, int x0,
                                     int width) {
  std::vector<cv::Point> at;
  int x = x0, line = 0;
  for (const auto& entry : entries) {
    int baseline = 0;
    const int w =
        cv::getTextSize(entry.text, cv::FONT_HERSHEY_SIMPLEX, 0.4, 1, &baseline).width + 30;
    if (x > x0 && x + w > width) {
      x = x0;
      ++line;
    }
    at.emplace_back(x, line * kLegendLine);
    x += w;
  }
  return at;
}

}  // namespace

cv::Scalar knotting_trial_colour(const EvaluatedTrial& trial,
                                 const std::vector<std::string>& categories) {
  return trial.success ? kSuccessGreen : category_colour(category_of(trial.failure, categories));
}

std::vector<KnottingLegendEntry> knotting_failure_legend(
    const std::vector<EvaluatedTrial>& trials, const std::vector<std::string>& categories) {
  std::vector<bool> seen(categories.size() + 1, false);  // the last: other
  for (const auto& trial : trials) {
    if (trial.success) continue;
    const int c = category_of(trial.failure, categories);
    seen[c < 0 ? categories.size() : static_cast<size_t>(c)] = true;
  }
  std::vector<KnottingLegendEntry> entries;
  for (size_t c = 0; c < categories.size(); ++c) {
    if (seen[c]) entries.push_back({categories[c], category_colour(static_cast<int>(c))});
  }
  if (seen.back()) entries.push_back({"other failure", kOtherFailure});
  return entries;
}

void write_knotting_figure(const std::vector<EvaluatedTrial>& trials,
                           const std::vector<Demonstration>& train,
                           const std::vector<std::string>& categories,
                           const std::string& png_path) {
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
  std::vector<KnottingLegendEntry> legend{{"training demonstrations", kPlotLightGrey},
                                          {"knot tied", kSuccessGreen}};
  for (auto& entry : knotting_failure_legend(trials, categories)) legend.push_back(entry);
  const std::vector<cv::Point> at = legend_layout(legend, 10, 2 * kPanel - 10);
  const int legend_height = (at.empty() ? 0 : at.back().y) + kLegendLine + 30;

  cv::Mat canvas(kPanel + legend_height, 2 * kPanel, CV_8UC3, kPlotWhite);
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
    const cv::Scalar colour = knotting_trial_colour(trial, categories);
    if (trial.generated.count("cor")) {
      draw_polyline(canvas, left, top_view(trial.generated.at("cor")), colour, 1);
    }
    if (trial.contexts.count("cor")) {
      if (auto p = context_point(trial.contexts.at("cor"))) draw_dot(canvas, right, *p, colour);
    }
  }
  const int top = kPanel + 20;
  for (size_t i = 0; i < legend.size(); ++i) {
    const cv::Point origin(at[i].x, top + at[i].y);
    cv::circle(canvas, origin + cv::Point(6, -4), 5, legend[i].colour, cv::FILLED, cv::LINE_AA);
    const bool faint = legend[i].colour == kPlotLightGrey;  // its text would hardly show
    put_text(canvas, legend[i].text, origin + cv::Point(16, 0), 0.4,
             faint ? kPlotGrey : legend[i].colour);
  }
  write_png(canvas, png_path, "write_knotting_figure");
}

}  // namespace corrmp
