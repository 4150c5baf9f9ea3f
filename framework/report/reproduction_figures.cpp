// The reproduction report's figures (reproduction_figures.hpp).
#include "report/reproduction_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "plot/interval_chart.hpp"
#include "plot/line_figure.hpp"
#include "report/metric_ranges.hpp"
#include "store/run_queries.hpp"

namespace corrmp {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const char* const kFiguresFolder = "figures";
const cv::Scalar kGroundTruthGrey(150, 150, 150);
const cv::Scalar kExecutionBlack(0, 0, 0);

// ---- shared -------------------------------------------------------------

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// A finite number written as the whole text, else nothing.
std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

double number_or_nan(const std::string& text) { return parse_number(text).value_or(kNaN); }

size_t column_index(const std::vector<std::string>& header, const std::string& name,
                    const std::string& path) {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) {
    throw std::runtime_error(fmt::format("'{}' has no column '{}'", path, name));
  }
  return static_cast<size_t>(it - header.begin());
}

std::string seed_text(const RunSummary& run) {
  const auto seed = run_setting(run, "seed");
  return seed ? *seed : std::string("?");
}

std::string run_name(const RunSummary& run) {
  return fmt::format("{} run {} (seed {})", run.experiment, run.id, seed_text(run));
}

// The run's directory, or nothing with a note naming what is missing.
std::optional<fs::path> run_directory(const RunSummary& run, const RunFiles* files,
                                      const std::string& figure, FigureSet& set) {
  if (files == nullptr || files->recorded.empty()) {
    set.notes.push_back(
        fmt::format("{}: skipped, {} records no run directory", figure, run_name(run)));
    return std::nullopt;
  }
  if (files->directory.empty()) {
    set.notes.push_back(fmt::format("{}: skipped, the directory '{}' of {} does not exist", figure,
                                    files->recorded, run_name(run)));
    return std::nullopt;
  }
  return fs::path(files->directory);
}

const RunFiles* files_of(const RunFilesById& files, const RunSummary& run) {
  const auto it = files.find(run.id);
  return it == files.end() ? nullptr : &it->second;
}

fs::path figure_path(const std::string& report_dir, const std::string& name) {
  const fs::path folder = fs::path(report_dir) / kFiguresFolder;
  fs::create_directories(folder);
  return folder / (name + ".png");
}

std::string relative_figure(const std::string& name) {
  return std::string(kFiguresFolder) + "/" + name + ".png";
}

// ---- 1. ground truth against prediction ----------------------------------

struct SegmentPath {
  std::vector<double> h, v, expert_h, expert_v;
  std::vector<double> executed_h, executed_v;  // NaN where not executed; empty: not in the file
};
struct TrialPaths {
  std::vector<std::pair<std::string, SegmentPath>> segments;  // in file order
  SegmentPath* find(const std::string& segment) {
    for (auto& [name, path] : segments) {
      if (name == segment) return &path;
    }
    return nullptr;
  }
};

// The index of column `name`, if the header has it.
std::optional<size_t> optional_column(const std::vector<std::string>& header,
                                      const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) return std::nullopt;
  return static_cast<size_t>(it - header.begin());
}

// The wanted trials' paths in the view's columns, scaled; every segment's name
// in order of first appearance goes to `segment_order`. The executed path is
// read when the file has its columns (files written before it was recorded do
// not); `has_executed` says whether it has.
std::map<int, TrialPaths> read_trajectories(const std::string& path, const TrajectoryView& view,
                                            const std::set<int>& wanted,
                                            std::vector<std::string>& segment_order,
                                            bool& has_executed) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) throw std::runtime_error("cannot read '" + path + "'");
  const auto header = split_csv_line(line);
  const size_t trial = column_index(header, "trial", path);
  const size_t segment = column_index(header, "segment", path);
  const size_t h = column_index(header, view.horizontal, path);
  const size_t v = column_index(header, view.vertical, path);
  const size_t eh = column_index(header, "expert_" + view.horizontal, path);
  const size_t ev = column_index(header, "expert_" + view.vertical, path);
  const auto xh = optional_column(header, "executed_" + view.horizontal);
  const auto xv = optional_column(header, "executed_" + view.vertical);
  has_executed = xh && xv;
  const size_t needed = std::max({trial, segment, h, v, eh, ev}) + 1;
  std::map<int, TrialPaths> trials;
  while (std::getline(in, line)) {
    const auto cells = split_csv_line(line);
    if (cells.size() < needed) continue;
    const auto index = parse_number(cells[trial]);
    if (!index) continue;
    const std::string& name = cells[segment];
    if (std::find(segment_order.begin(), segment_order.end(), name) == segment_order.end()) {
      segment_order.push_back(name);
    }
    if (!wanted.count(static_cast<int>(*index))) continue;
    TrialPaths& paths = trials[static_cast<int>(*index)];
    SegmentPath* p = paths.find(name);
    if (p == nullptr) p = &paths.segments.emplace_back(name, SegmentPath{}).second;
    p->h.push_back(view.scale * number_or_nan(cells[h]));
    p->v.push_back(view.scale * number_or_nan(cells[v]));
    p->expert_h.push_back(view.scale * number_or_nan(cells[eh]));
    p->expert_v.push_back(view.scale * number_or_nan(cells[ev]));
    if (has_executed) {
      p->executed_h.push_back(*xh < cells.size() ? view.scale * number_or_nan(cells[*xh]) : kNaN);
      p->executed_v.push_back(*xv < cells.size() ? view.scale * number_or_nan(cells[*xv]) : kNaN);
    }
  }
  return trials;
}

// The trial shown for an expected correction: a matched, successful one if
// any, else a matched one, else the first.
const TrialDecision* representative_trial(const std::vector<TrialDecision>& trials,
                                          const std::string& label) {
  const TrialDecision* matched = nullptr;
  const TrialDecision* first = nullptr;
  for (const auto& t : trials) {
    if (t.expected != label) continue;
    if (t.chosen == label && t.success) return &t;
    if (t.chosen == label && matched == nullptr) matched = &t;
    if (first == nullptr) first = &t;
  }
  return matched != nullptr ? matched : first;
}

cv::Scalar segment_colour(const std::vector<std::string>& order, const std::string& segment) {
  const auto it = std::find(order.begin(), order.end(), segment);
  return series_colour(static_cast<size_t>(it - order.begin()));
}

// Whether the path has an executed point to draw.
bool executed_drawn(const SegmentPath& path) {
  for (size_t i = 0; i < path.executed_h.size() && i < path.executed_v.size(); ++i) {
    if (std::isfinite(path.executed_h[i]) && std::isfinite(path.executed_v[i])) return true;
  }
  return false;
}

void add_paths(LinePanel& panel, const std::string& segment, const SegmentPath& path,
               const std::vector<std::string>& order) {
  // Every expert path first, so the predictions are drawn over them, and the
  // executions over those.
  panel.lines.insert(panel.lines.begin(),
                     PlotLine{path.expert_h, path.expert_v, kGroundTruthGrey, 2, true});
  panel.lines.push_back(PlotLine{path.h, path.v, segment_colour(order, segment), 2, false});
  if (executed_drawn(path)) {
    panel.lines.push_back(PlotLine{path.executed_h, path.executed_v, kExecutionBlack, 1, false});
  }
}

// ---- 2. success against a parameter --------------------------------------

std::string group_of(const RunSummary& run, const std::string& key) {
  std::string group = key == "experiment" ? "" : run.experiment;
  for (const auto& [axis, value] : run.axes) {
    if (axis == key || is_seed_key(axis)) continue;
    group += fmt::format("{}{}={}", group.empty() ? "" : ", ", axis, value);
  }
  return group;
}

std::string file_name_of(const std::string& key) {
  std::string name = key;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

// ---- 3. training curves --------------------------------------------------

// The mean curve of `curves` over the updates every one of them has.
std::pair<std::vector<double>, std::vector<std::vector<double>>> mean_curve(
    const std::vector<const TrainingCurve*>& curves) {
  std::vector<double> updates = curves.front()->updates;
  for (const auto* curve : curves) {
    std::vector<double> kept;
    for (double u : updates) {
      if (std::find(curve->updates.begin(), curve->updates.end(), u) != curve->updates.end()) {
        kept.push_back(u);
      }
    }
    updates = kept;
  }
  std::vector<std::vector<double>> means(2, std::vector<double>(updates.size(), 0.0));
  for (size_t i = 0; i < updates.size(); ++i) {
    for (const auto* curve : curves) {
      const size_t at =
          static_cast<size_t>(std::find(curve->updates.begin(), curve->updates.end(), updates[i]) -
                              curve->updates.begin());
      means[0][i] += curve->loss[at] / static_cast<double>(curves.size());
      means[1][i] += curve->validation_mean[at] / static_cast<double>(curves.size());
    }
  }
  return {updates, means};
}

}  // namespace

// ---- run files -------------------------------------------------------------

RunFilesById load_run_files(ResultStore& store, const std::vector<RunSummary>& runs) {
  std::vector<fs::path> bases{fs::current_path()};
  for (fs::path folder = fs::absolute(store.path()).parent_path();; folder = folder.parent_path()) {
    bases.push_back(folder);
    if (folder == folder.parent_path()) break;
  }
  RunFilesById out;
  for (const auto& run : runs) {
    RunFiles files;
    files.recorded = run.out_dir;
    if (!files.recorded.empty()) {
      const fs::path recorded(files.recorded);
      if (recorded.is_absolute()) {
        if (fs::is_directory(recorded)) files.directory = recorded.string();
      } else {
        for (const auto& base : bases) {
          if (fs::is_directory(base / recorded)) {
            files.directory = (base / recorded).string();
            break;
          }
        }
      }
    }
    for (const TrialRecord& trial : run_trials(store, run.id)) {
      files.trials.push_back(
          {trial.trial, trial.expected_action, trial.chosen_action, trial.success});
    }
    out[run.id] = std::move(files);
  }
  return out;
}

const RunSummary* first_seed_run(const std::vector<RunSummary>& runs,
                                 const std::string& experiment) {
  const RunSummary* best = nullptr;
  double best_seed = std::numeric_limits<double>::infinity();
  for (const auto& run : runs) {
    if (run.experiment != experiment) continue;
    const auto seed = run_setting(run, "seed");
    const double value = seed ? parse_number(*seed).value_or(kNaN) : kNaN;
    const double key = std::isfinite(value) ? value : std::numeric_limits<double>::max();
    if (best == nullptr || key < best_seed || (key == best_seed && run.id < best->id)) {
      best = &run;
      best_seed = key;
    }
  }
  return best;
}

// ---- 1 -----------------------------------------------------------------------

void add_trajectory_comparison(FigureSet& set, const RunSummary& run, const RunFiles& files,
                               const TrajectoryView& view, const std::string& report_dir,
                               const std::string& name) {
  const std::string figure = "ground truth vs prediction (" + run.experiment + ")";
  const auto directory = run_directory(run, &files, figure, set);
  if (!directory) return;
  const fs::path csv = *directory / "trajectories.csv";
  if (!fs::exists(csv)) {
    set.notes.push_back(
        fmt::format("{}: skipped, {} has no {}", figure, run_name(run), csv.string()));
    return;
  }
  std::vector<std::string> labels = view.labels;
  for (const auto& t : files.trials) {
    if (!t.expected.empty() && std::find(labels.begin(), labels.end(), t.expected) == labels.end())
      labels.push_back(t.expected);
  }
  std::vector<std::pair<std::string, const TrialDecision*>> shown;
  std::vector<std::string> absent;
  std::set<int> wanted;
  for (const auto& label : labels) {
    const TrialDecision* trial = representative_trial(files.trials, label);
    if (trial == nullptr) {
      absent.push_back(label);
      continue;
    }
    shown.emplace_back(label, trial);
    wanted.insert(trial->trial);
  }
  if (shown.empty()) {
    set.notes.push_back(fmt::format("{}: skipped, {} records no trial with an expected correction",
                                    figure, run_name(run)));
    return;
  }
  std::vector<std::string> order = view.segments;
  std::map<int, TrialPaths> paths;
  bool has_executed = false;
  try {
    paths = read_trajectories(csv.string(), view, wanted, order, has_executed);
  } catch (const std::runtime_error& e) {
    set.notes.push_back(fmt::format("{}: skipped, {}", figure, e.what()));
    return;
  }

  LineFigure plot;
  // One correction: its two panels side by side.
  plot.columns = shown.size() == 1 ? 2 : static_cast<int>(shown.size());
  plot.panel_width = plot.panel_height = kTrajectoryComparisonPanel;
  plot.heading = fmt::format("{}: {} up, {} right ({})", run_name(run), view.vertical,
                             view.horizontal, view.unit);
  plot.legend.push_back({"ground truth (expert)", kGroundTruthGrey, 2, true});
  for (const auto& segment : order) {
    const bool drawn = std::any_of(paths.begin(), paths.end(), [&](auto& trial) {
      return trial.second.find(segment) != nullptr;
    });
    if (drawn) {
      plot.legend.push_back({"prediction " + segment, segment_colour(order, segment), 2, false});
    }
  }
  const bool executed = std::any_of(paths.begin(), paths.end(), [](const auto& trial) {
    return std::any_of(trial.second.segments.begin(), trial.second.segments.end(),
                       [](const auto& segment) { return executed_drawn(segment.second); });
  });
  if (executed) plot.legend.push_back({"execution", kExecutionBlack, 1, false});
  const std::string x_label = fmt::format("{} ({})", view.horizontal, view.unit);
  std::vector<LinePanel> whole, focus;
  std::string chosen_text;
  for (const auto& [label, trial] : shown) {
    LinePanel top{fmt::format("{}: trial {}, chose {}, {}", label, trial->trial,
                              trial->chosen.empty() ? "undecided" : trial->chosen,
                              trial->success ? "ok" : "failed"),
                  x_label,
                  {},
                  {},
                  {},
                  "no trajectories"};
    LinePanel bottom{fmt::format("{} segment of trial {}", view.focus_segment, trial->trial),
                     x_label,
                     {},
                     {},
                     {},
                     "no " + view.focus_segment + " segment"};
    auto it = paths.find(trial->trial);
    if (it != paths.end()) {
      for (const auto& [segment, path] : it->second.segments) {
        add_paths(top, segment, path, order);
        if (segment == view.focus_segment) add_paths(bottom, segment, path, order);
      }
    }
    whole.push_back(std::move(top));
    focus.push_back(std::move(bottom));
    chosen_text +=
        fmt::format("{}{}: trial {}, chose {}, {}", chosen_text.empty() ? "" : "; ", label,
                    trial->trial, trial->chosen.empty() ? "undecided" : trial->chosen,
                    trial->success ? "succeeded" : "failed");
  }
  plot.panels = whole;
  plot.panels.insert(plot.panels.end(), focus.begin(), focus.end());
  write_png(draw_line_figure(plot), figure_path(report_dir, name).string(),
            "add_trajectory_comparison");

  const std::string curves =
      executed ? "the expert's demonstration of the trial's scenario (ground truth, grey dashed), "
                 "the trajectory the policy generated (prediction, coloured by segment) and the "
                 "path the effectors executed following it (execution, thin black)"
               : "the expert's demonstration of the trial's scenario (ground truth, grey dashed) "
                 "and the trajectory the policy generated (prediction, coloured by segment)";
  std::string caption = fmt::format(
      "Ground truth vs prediction{}, {} (the paper's comparison of ground truth, prediction and "
      "execution for the {}-MPs): for one trial of each expected correction ({}), {}, top view in "
      "{}; below, the {} segment alone (in a single column, beside it)",
      executed ? " vs execution" : "", run_name(run), view.focus_segment, chosen_text, curves,
      view.unit, view.focus_segment);
  if (!executed) {
    caption += has_executed ? ". The paper's third curve, the executed motion, is not drawn: the "
                              "task recorded no executed path for these trials"
                            : ". The paper's third curve, the executed motion, is not drawn: "
                              "this trajectories.csv has no executed columns (it was written "
                              "before executions were recorded), only the generated and the "
                              "expert trajectories";
  }
  if (!view.execution_note.empty()) caption += "; " + view.execution_note;
  if (!absent.empty()) {
    std::string list;
    for (const auto& label : absent) list += (list.empty() ? "'" : ", '") + label + "'";
    caption += fmt::format(". No trial of this run had the expected correction {}", list);
  }
  set.figures.push_back({relative_figure(name), caption + "."});
}

// ---- 2 -----------------------------------------------------------------------

std::vector<std::string> swept_numeric_axes(const std::vector<RunSummary>& runs) {
  std::map<std::string, std::set<std::string>> values;
  std::set<std::string> not_numeric;
  for (const auto& run : runs) {
    for (const auto& [axis, value] : run.axes) {
      if (is_seed_key(axis)) continue;
      values[axis].insert(value);
      if (!parse_number(value)) not_numeric.insert(axis);
    }
  }
  std::vector<std::string> axes;
  for (const auto& [axis, distinct] : values) {
    if (!not_numeric.count(axis) && distinct.size() >= 2) axes.push_back(axis);
  }
  return axes;
}

SuccessByParameter success_by_parameter(const std::vector<RunSummary>& runs,
                                        const std::string& key) {
  SuccessByParameter out;
  out.key = key;
  // Per group, per value: the runs' success rates.
  std::vector<std::string> groups;
  std::map<std::string, std::map<std::string, std::vector<double>>> samples;
  for (const auto& run : runs) {
    const auto value = run_setting(run, key);
    const auto rate = run.metrics.find("task_success_rate");
    if (!value || rate == run.metrics.end()) {
      ++out.skipped_runs;
      continue;
    }
    const std::string group = group_of(run, key);
    if (!samples.count(group)) groups.push_back(group);
    if (std::find(out.values.begin(), out.values.end(), *value) == out.values.end()) {
      out.values.push_back(*value);
    }
    samples[group][*value].push_back(rate->second);
  }
  out.numeric = !out.values.empty() &&
                std::all_of(out.values.begin(), out.values.end(),
                            [](const std::string& v) { return parse_number(v).has_value(); });
  if (out.numeric) {
    std::stable_sort(out.values.begin(), out.values.end(),
                     [](const std::string& a, const std::string& b) {
                       return *parse_number(a) < *parse_number(b);
                     });
  }
  for (const auto& group : groups) {
    SuccessSeries series{group, {}};
    for (size_t i = 0; i < out.values.size(); ++i) {
      const auto it = samples[group].find(out.values[i]);
      if (it == samples[group].end()) continue;
      const double x = out.numeric ? *parse_number(out.values[i]) : static_cast<double>(i);
      series.points.push_back({out.values[i], x, mean_interval(it->second)});
    }
    out.series.push_back(std::move(series));
  }
  return out;
}

void write_success_figure(const SuccessByParameter& data, const std::string& png_path) {
  IntervalChart chart;
  const bool per_experiment = data.key == "experiment";
  chart.title = per_experiment
                    ? "Task success per experiment: mean across seeds, 95% interval clipped "
                      "to 0-100%"
                    : fmt::format(
                          "Task success against {}: mean across seeds, 95% interval clipped to "
                          "0-100%",
                          data.key);
  chart.x_label = data.key;
  chart.y_label = "task success (%)";
  chart.y_min = 0.0;
  chart.y_max = 100.0;
  chart.y_grid = {0.0, 25.0, 50.0, 75.0, 100.0};
  if (!data.numeric) chart.categories = data.values;
  for (const auto& series : data.series) {
    IntervalSeries drawn{series.group.empty() ? "task success" : series.group, {}};
    for (const auto& point : series.points) {
      const MeanInterval& m = point.success;
      const IntervalBounds bounds = metric_interval(rate_metric(Better::higher), m);
      drawn.points.push_back({point.x, 100.0 * m.mean, 100.0 * bounds.low, 100.0 * bounds.high});
    }
    chart.series.push_back(std::move(drawn));
  }
  write_png(draw_interval_chart(chart), png_path, "write_success_figure");
}

std::string success_csv(const SuccessByParameter& data) {
  auto number = [](double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : ""; };
  std::string out = "group,value,runs,mean,ci_low,ci_high\n";
  for (const auto& series : data.series) {
    for (const auto& p : series.points) {
      const IntervalBounds bounds = metric_interval(rate_metric(Better::higher), p.success);
      out += fmt::format("{},{},{},{},{},{}\n", series.group, p.value, p.success.count,
                         number(p.success.mean), number(bounds.low), number(bounds.high));
    }
  }
  return out;
}

void add_success_figures(FigureSet& set, const std::vector<RunSummary>& runs,
                         const std::string& report_dir) {
  std::vector<std::string> keys = swept_numeric_axes(runs);
  if (keys.empty()) keys.push_back("experiment");
  for (const auto& key : keys) {
    const SuccessByParameter data = success_by_parameter(runs, key);
    if (data.series.empty()) {
      set.notes.push_back(
          fmt::format("task success against {}: skipped, no run has a task success rate", key));
      continue;
    }
    const std::string name = "success_vs_" + file_name_of(key);
    write_success_figure(data, figure_path(report_dir, name).string());
    std::string caption =
        key == "experiment"
            ? "Task success per experiment: the mean of the runs' task success rates across "
              "seeds (dots) with its 95% Student t interval (bars, clipped to 0-100%; none "
              "with one run)"
            : fmt::format(
                  "Task success against {}: the mean of the runs' task success rates "
                  "across seeds (dots, one line per group) with its 95% Student t "
                  "interval (bars, clipped to 0-100%; none with one run)",
                  key);
    if (data.skipped_runs > 0) {
      caption += fmt::format("; {} run{} without a task success rate or {} left out",
                             data.skipped_runs, data.skipped_runs == 1 ? "" : "s", key);
    }
    set.figures.push_back({relative_figure(name), caption + "."});
  }
}

// ---- 3 -----------------------------------------------------------------------

std::vector<TrainingCurve> read_training_curves(const std::string& csv_path) {
  std::ifstream in(csv_path);
  std::string line;
  if (!in || !std::getline(in, line)) {
    throw std::runtime_error("cannot read '" + csv_path + "'");
  }
  const auto header = split_csv_line(line);
  const size_t network = column_index(header, "network", csv_path);
  const size_t update = column_index(header, "update", csv_path);
  const size_t loss = column_index(header, "loss", csv_path);
  const size_t validation = column_index(header, "validation_error_mean", csv_path);
  const size_t needed = std::max({network, update, loss, validation}) + 1;
  std::vector<TrainingCurve> curves;
  while (std::getline(in, line)) {
    const auto cells = split_csv_line(line);
    if (cells.size() < needed || cells[network].empty()) continue;
    const auto at = parse_number(cells[update]);
    if (!at) continue;
    auto it = std::find_if(curves.begin(), curves.end(),
                           [&](const TrainingCurve& c) { return c.network == cells[network]; });
    if (it == curves.end()) {
      curves.push_back({cells[network], {}, {}, {}});
      it = curves.end() - 1;
    }
    it->updates.push_back(*at);
    it->loss.push_back(number_or_nan(cells[loss]));
    it->validation_mean.push_back(number_or_nan(cells[validation]));
  }
  return curves;
}

void add_training_curves(FigureSet& set, const std::string& experiment,
                         const std::vector<const RunSummary*>& runs, const RunFilesById& files,
                         const std::string& report_dir) {
  const std::string figure = "training curves (" + experiment + ")";
  std::vector<std::pair<const RunSummary*, std::vector<TrainingCurve>>> read;
  for (const RunSummary* run : runs) {
    const auto directory = run_directory(*run, files_of(files, *run), figure, set);
    if (!directory) continue;
    const fs::path csv = *directory / "training_curves.csv";
    if (!fs::exists(csv)) {
      set.notes.push_back(
          fmt::format("{}: {} has no training_curves.csv (a run older than the "
                      "file), left out",
                      figure, run_name(*run)));
      continue;
    }
    try {
      read.emplace_back(run, read_training_curves(csv.string()));
    } catch (const std::runtime_error& e) {
      set.notes.push_back(fmt::format("{}: {}, left out", figure, e.what()));
    }
  }
  std::vector<std::string> networks;
  for (const auto& [run, curves] : read) {
    for (const auto& c : curves) {
      if (std::find(networks.begin(), networks.end(), c.network) == networks.end()) {
        networks.push_back(c.network);
      }
    }
  }
  if (networks.empty()) {
    set.notes.push_back(fmt::format("{}: skipped, no run has training curves", figure));
    return;
  }
  // Runs with the same non-seed sweep axes (e.g. updates=20000) form a group;
  // a mean is taken within a group only.
  std::vector<std::string> groups;
  std::vector<size_t> group_index;
  for (const auto& [run, curves] : read) {
    const std::string group = group_of(*run, "experiment");
    auto it = std::find(groups.begin(), groups.end(), group);
    if (it == groups.end()) it = groups.insert(groups.end(), group);
    group_index.push_back(static_cast<size_t>(it - groups.begin()));
  }
  const bool one_group = groups.size() == 1;
  auto run_colour = [&](size_t r) { return series_colour(one_group ? r : group_index[r]); };
  auto mean_colour = [&](size_t g) { return one_group ? kPlotBlack : series_colour(g); };

  LineFigure plot;
  // Loss panels in the first row, validation panels in the second; one
  // network's two panels side by side.
  plot.columns = networks.size() == 1 ? 2 : static_cast<int>(networks.size());
  std::string seeds;
  for (size_t r = 0; r < read.size(); ++r) {
    const RunSummary& run = *read[r].first;
    if (one_group) {
      plot.legend.push_back(
          {fmt::format("seed {} (run {})", seed_text(run), run.id), run_colour(r), 1, false});
    }
    seeds += (seeds.empty() ? "" : ", ") + seed_text(run);
  }
  for (size_t g = 0; g < groups.size(); ++g) {
    const auto count = std::count(group_index.begin(), group_index.end(), g);
    if (one_group && count > 1) plot.legend.push_back({"mean across seeds", kPlotBlack, 2, false});
    if (!one_group) {
      plot.legend.push_back({fmt::format("{} ({} run{})", groups[g], count, count == 1 ? "" : "s"),
                             mean_colour(g), 2, false});
    }
  }
  plot.heading = fmt::format("{}: training curves of {} run{} (seed{} {})", experiment, read.size(),
                             read.size() == 1 ? "" : "s", read.size() == 1 ? "" : "s", seeds);
  for (int row = 0; row < 2; ++row) {
    for (const auto& network : networks) {
      LinePanel panel{fmt::format("{}: {}", network, row == 0 ? "loss (NLL)" : "validation error"),
                      "update",
                      {},
                      {},
                      {},
                      row == 0 ? "no loss" : "no validation data"};
      std::vector<std::vector<const TrainingCurve*>> of_group(groups.size());
      for (size_t r = 0; r < read.size(); ++r) {
        for (const auto& c : read[r].second) {
          if (c.network != network) continue;
          of_group[group_index[r]].push_back(&c);
          panel.lines.push_back(
              {c.updates, row == 0 ? c.loss : c.validation_mean, run_colour(r), 1, false});
        }
      }
      for (size_t g = 0; g < groups.size(); ++g) {
        if (of_group[g].size() < 2) continue;
        const auto [updates, means] = mean_curve(of_group[g]);
        panel.lines.push_back({updates, means[row], mean_colour(g), 2, false});
      }
      plot.panels.push_back(std::move(panel));
    }
  }
  const std::string name = "training_curves_" + file_name_of(experiment);
  write_png(draw_line_figure(plot), figure_path(report_dir, name).string(), "add_training_curves");
  std::string lines = "one thin line per seed";
  if (!one_group) {
    lines =
        "one thin line per run, coloured by its setting, and the mean across the seeds of "
        "each setting thick";
  } else if (read.size() > 1) {
    lines += ", their mean in black";
  }
  set.figures.push_back(
      {relative_figure(name),
       fmt::format("Training curves of {} (training_curves.csv of each run): per network, the "
                   "training loss (Gaussian negative log-likelihood, averaged over the updates "
                   "since the previous point) and the mean validation error against updates; {}.",
                   experiment, lines)});
}

// ---- 4 -----------------------------------------------------------------------

void add_copied_figure(FigureSet& set, const RunSummary& run, const RunFiles& files,
                       const std::string& file, const std::string& report_dir,
                       const std::string& name, const std::string& caption) {
  const std::string figure = file + " (" + run.experiment + ")";
  const auto directory = run_directory(run, &files, figure, set);
  if (!directory) return;
  const fs::path source = *directory / file;
  if (!fs::is_regular_file(source)) {
    set.notes.push_back(
        fmt::format("{}: skipped, {} has no {}", figure, run_name(run), source.string()));
    return;
  }
  fs::copy_file(source, figure_path(report_dir, name), fs::copy_options::overwrite_existing);
  set.figures.push_back({relative_figure(name), caption});
}

// ---- all -----------------------------------------------------------------------

FigureSet reproduction_figures(const std::vector<RunSummary>& runs, const RunFilesById& files,
                               const std::string& report_dir, const ReproductionFiguresSpec& spec) {
  FigureSet set;
  static const RunFiles kNoFiles;
  auto files_for = [&](const RunSummary& run) {
    const RunFiles* f = files_of(files, run);
    return f != nullptr ? *f : kNoFiles;
  };
  for (const auto& comparison : spec.trajectory_comparisons) {
    for (const auto& experiment : comparison.experiments) {
      if (const RunSummary* run = first_seed_run(runs, experiment)) {
        add_trajectory_comparison(set, *run, files_for(*run), comparison.view, report_dir,
                                  "ground_truth_vs_prediction_" + experiment);
      }
    }
  }

  add_success_figures(set, runs, report_dir);

  std::vector<std::string> experiments;
  for (const auto& run : runs) {
    if (std::find(experiments.begin(), experiments.end(), run.experiment) == experiments.end()) {
      experiments.push_back(run.experiment);
    }
  }
  for (const auto& experiment : experiments) {
    std::vector<const RunSummary*> of_experiment;
    for (const auto& run : runs) {
      if (run.experiment == experiment) of_experiment.push_back(&run);
    }
    add_training_curves(set, experiment, of_experiment, files, report_dir);
  }

  for (const auto& copied : spec.copied) {
    if (const RunSummary* run = first_seed_run(runs, copied.experiment)) {
      std::string caption = copied.caption;
      const std::string placeholder = "{run}", name = run_name(*run);
      for (size_t at = caption.find(placeholder); at != std::string::npos;
           at = caption.find(placeholder, at + name.size())) {
        caption.replace(at, placeholder.size(), name);
      }
      add_copied_figure(set, *run, files_for(*run), copied.file, report_dir, copied.name, caption);
    }
  }
  return set;
}

}  // namespace corrmp
