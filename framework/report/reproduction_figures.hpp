// The reproduction report's figures (report --reproduction; docs/sweeps.md,
// "Comparing and reporting"), drawn from a sweep's runs and the files in
// their run directories:
//  1. ground truth against prediction and execution for one trial of each
//     expected correction (the paper's Fig. "Comparison of ground-truth,
//     prediction, and robot execution for different cor-MPs"), from
//     trajectories.csv of the first seed's run;
//  2. task success against a swept numeric parameter, or per experiment for a
//     sweep over seeds only: the mean across seeds with its 95% interval;
//  3. training curves (loss and validation error against updates per
//     network), from each run's training_curves.csv;
//  4. figures the runs wrote themselves (a context's or a task's), copied
//     from the first seed's run directory.
// Which experiments get figures 1 and 4, and how, is data
// (ReproductionFiguresSpec). Each figure is written to <report dir>/figures/
// and listed with a caption; a missing input (no run directory, no file)
// skips the figure with a note.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "report/run_summaries.hpp"
#include "stats/mean_interval.hpp"
#include "store/result_store.hpp"

namespace corrmp {

// A figure of the report: its path (relative to the report's folder, or
// absolute) and its caption.
struct ReportFigure {
  std::string path;
  std::string caption;
};

// A trial's decision as the trials table records it.
struct TrialDecision {
  int trial = 0;
  std::string expected, chosen;
  bool success = false;
};

// What the figures read of a run besides its summary.
struct RunFiles {
  std::string recorded;   // runs.out_dir as recorded ("" when none)
  std::string directory;  // where it was found; "" when it does not exist
  std::vector<TrialDecision> trials;
};
using RunFilesById = std::map<int64_t, RunFiles>;

// The runs' directories and trials. A relative out_dir is looked for from the
// current directory, then from the database's folder and each of its parents.
RunFilesById load_run_files(ResultStore& store, const std::vector<RunSummary>& runs);

// The figures made (paths relative to the report's folder) and notes on the
// ones skipped.
struct FigureSet {
  std::vector<ReportFigure> figures;
  std::vector<std::string> notes;
};

// The run of `experiment` with the lowest seed (ties: the lowest id);
// nullptr when there is none.
const RunSummary* first_seed_run(const std::vector<RunSummary>& runs,
                                 const std::string& experiment);

// ---- 1. Ground truth against prediction --------------------------------

struct TrajectoryView {
  std::string horizontal, vertical;   // trajectory columns (e.g. y right, x up: a top view)
  std::string focus_segment;          // drawn alone in the second row
  std::vector<std::string> labels;    // the expected labels, one column each
  std::vector<std::string> segments;  // segment order (colours); others follow as read
  double scale = 1.0;                 // trajectory units to the figure's unit
  std::string unit;
  std::string execution_note = "";  // what the caption says of the executed path, if anything

  template <class Fields>
  void describe(Fields& f) {
    f("horizontal", horizontal, "the trajectory column drawn to the right", required());
    f("vertical", vertical, "the trajectory column drawn up", required());
    f("focus_segment", focus_segment, "the segment drawn alone in the second row", required());
    f("labels", labels, "the expected labels, one column each", required());
    f("segments", segments, "the segments' order (their colours)", required());
    f("scale", scale, "trajectory units to the figure's unit", positive());
    f("unit", unit, "the figure's unit", required());
    f("execution_note", execution_note, "what the caption says of the executed path");
  }
};

// One column per label that a trial of the run expected (the first such trial
// whose choice matched and succeeded, else whose choice matched, else the
// first): the whole skill above, the focus segment below, the expert's path
// (ground truth, grey dashed) beneath the generated one (prediction, coloured
// by segment) and, where the file has executed_ columns with values, the
// executed path over it (execution, thin black; the legend and caption name
// it only when drawn); a single column's two panels side by side. Written to
// report_dir/figures/<name>.png.
constexpr int kTrajectoryComparisonPanel = 320;  // width and height of a panel
void add_trajectory_comparison(FigureSet& set, const RunSummary& run, const RunFiles& files,
                               const TrajectoryView& view, const std::string& report_dir,
                               const std::string& name);

// ---- 2. Success against a swept parameter ------------------------------

// The sweep axes, other than seeds, whose values are all numbers and take two
// or more values across the runs; sorted.
std::vector<std::string> swept_numeric_axes(const std::vector<RunSummary>& runs);

struct SuccessAtValue {
  std::string value;  // as written
  double x = 0.0;     // the number, or the value's index on a categorical axis
  MeanInterval success;
};

struct SuccessSeries {
  std::string group;                   // the experiment and the other non-seed axes ("" if none)
  std::vector<SuccessAtValue> points;  // in axis order
};

struct SuccessByParameter {
  std::string key;
  bool numeric = false;             // every value a number
  std::vector<std::string> values;  // the axis: increasing, or in order of first run
  std::vector<SuccessSeries> series;
  int skipped_runs = 0;  // without the key or a task_success_rate
};

// Task success (each run's task_success_rate) against the setting `key`
// (run_setting: a sweep axis, the resolved config, or "experiment"), per
// group of runs with the same experiment (unless the key is the experiment)
// and other non-seed axis values: the mean across the group's runs at each
// value with its 95% Student t interval.
SuccessByParameter success_by_parameter(const std::vector<RunSummary>& runs,
                                        const std::string& key);

// The chart (plot/interval_chart.hpp, kIntervalChartWidth x
// kIntervalChartHeight): success in percent, with intervals clipped to
// [0, 100] (metric_ranges.hpp), as its title says. Throws std::runtime_error
// when the PNG cannot be written.
void write_success_figure(const SuccessByParameter& data, const std::string& png_path);

// group,value,runs,mean,ci_low,ci_high (rates; the intervals clipped to
// [0, 1] as in the chart, the means not).
std::string success_csv(const SuccessByParameter& data);

// Against each of swept_numeric_axes, or per experiment without one.
void add_success_figures(FigureSet& set, const std::vector<RunSummary>& runs,
                         const std::string& report_dir);

// ---- 3. Training curves -------------------------------------------------

struct TrainingCurve {
  std::string network;
  std::vector<double> updates, loss, validation_mean;  // NaN where empty
};

// The networks' curves of a training_curves.csv, in order of first row.
// Throws std::runtime_error when it cannot be read or lacks the columns.
std::vector<TrainingCurve> read_training_curves(const std::string& csv_path);

// Per network, loss above and validation error below against updates: one
// thin line per run (seed) and, with two or more runs, their mean. Runs
// without a directory or a training_curves.csv are skipped with a note.
void add_training_curves(FigureSet& set, const std::string& experiment,
                         const std::vector<const RunSummary*>& runs, const RunFilesById& files,
                         const std::string& report_dir);

// ---- 4. Copied figures --------------------------------------------------

// Copies <run dir>/<file> to report_dir/figures/<name>.png with the caption,
// or notes why it cannot.
void add_copied_figure(FigureSet& set, const RunSummary& run, const RunFiles& files,
                       const std::string& file, const std::string& report_dir,
                       const std::string& name, const std::string& caption);

// ---- The report's figures -------------------------------------------------

// Figure 1 for the first seed's run of each experiment, in one view.
struct TrajectoryComparisons {
  std::vector<std::string> experiments;
  TrajectoryView view;

  template <class Fields>
  void describe(Fields& f) {
    f("experiments", experiments, "the experiments drawn in this view", required());
    f("view", view, "the view", required());
  }
};

// Figure 4: a file of the first seed's run of the experiment; "{run}" in the
// caption names the run.
struct CopiedFigure {
  std::string experiment, file, name, caption;

  template <class Fields>
  void describe(Fields& f) {
    f("experiment", experiment, "the experiment whose first seed's run wrote the file", required());
    f("file", file, "the file in the run directory", required());
    f("name", name, "the figure's name in the report (without .png)", required());
    f("caption", caption, "the caption; {run} names the run", required());
  }
};

struct ReproductionFiguresSpec {
  std::vector<TrajectoryComparisons> trajectory_comparisons;
  std::vector<CopiedFigure> copied;

  template <class Fields>
  void describe(Fields& f) {
    f("trajectory_comparisons", trajectory_comparisons,
      "ground truth against prediction, per view");
    f("copied", copied, "figures the runs wrote, copied into the report");
  }
};

// Figures 1 (in the spec's order), 2, 3 (per experiment, in order of first
// run) and 4 (in the spec's order) for `runs`, written under
// report_dir/figures/.
FigureSet reproduction_figures(const std::vector<RunSummary>& runs, const RunFilesById& files,
                               const std::string& report_dir, const ReproductionFiguresSpec& spec);

}  // namespace corrmp
