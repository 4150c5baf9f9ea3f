// Tests of the reproduction report's figures: task success against a swept
// parameter (means and 95% intervals per axis value and group), the figure
// files written from small synthetic run directories with their sizes and
// captions, and missing inputs skipped with notes. Reference intervals:
// t(0.975, 1) = 12.7062047, t(0.975, 2) = 4.30265273 (mpmath).
#include "report/reproduction_figures.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "config/test_files.hpp"
#include "plot/interval_chart.hpp"
#include "plot/line_figure.hpp"
#include "report/reproduction_report.hpp"
#include "support/figure_runs.hpp"
#include "support/recorded_runs.hpp"

namespace corrmp {
namespace {

namespace fs = std::filesystem;
using testing::any_note;
using testing::contains;
using testing::files_in;
using testing::png_size;
using testing::run_of;
using testing::TempDir;
using testing::write_trajectories;

std::map<std::string, std::string> seeded(int seed, const std::string& updates) {
  return {{"seed", std::to_string(seed)},
          {"evaluation.seed", std::to_string(1000 + seed)},
          {"policy.training.updates", updates}};
}

// corridor_pc at 20000 updates: 0.5, 0.7; at 5000: 0.2, 0.4, 0.6;
// corridor_mono at 20000: 1.0, and a run at 100000 without a success rate.
std::vector<RunSummary> updates_sweep() {
  return {run_of(1, "corridor_pc", seeded(0, "20000"), 0.5),
          run_of(2, "corridor_pc", seeded(1, "20000"), 0.7),
          run_of(3, "corridor_pc", seeded(0, "5000"), 0.2),
          run_of(4, "corridor_pc", seeded(1, "5000"), 0.4),
          run_of(5, "corridor_pc", seeded(2, "5000"), 0.6),
          run_of(6, "corridor_mono", seeded(0, "20000"), 1.0),
          run_of(7, "corridor_mono", seeded(1, "100000"), std::nullopt)};
}

TEST(ReproductionFigures, SuccessAgainstANumericAxisHasMeansAndIntervalsPerValueAndGroup) {
  const SuccessByParameter data = success_by_parameter(updates_sweep(), "policy.training.updates");
  EXPECT_TRUE(data.numeric);
  EXPECT_EQ(data.values, (std::vector<std::string>{"5000", "20000"}));  // by number, not text
  EXPECT_EQ(data.skipped_runs, 1);
  ASSERT_EQ(data.series.size(), 2u);
  EXPECT_EQ(data.series[0].group, "corridor_pc");  // seeds make no group
  ASSERT_EQ(data.series[0].points.size(), 2u);
  const SuccessAtValue& low = data.series[0].points[0];
  EXPECT_EQ(low.value, "5000");
  EXPECT_EQ(low.x, 5000.0);
  EXPECT_EQ(low.success.count, 3);
  EXPECT_NEAR(low.success.mean, 0.4, 1e-12);
  EXPECT_NEAR(low.success.low, 0.4 - 4.30265273 * 0.2 / std::sqrt(3.0), 1e-7);
  EXPECT_NEAR(low.success.high, 0.4 + 4.30265273 * 0.2 / std::sqrt(3.0), 1e-7);
  const SuccessAtValue& high = data.series[0].points[1];
  EXPECT_EQ(high.x, 20000.0);
  EXPECT_EQ(high.success.count, 2);
  EXPECT_NEAR(high.success.mean, 0.6, 1e-12);
  EXPECT_NEAR(high.success.high - high.success.mean, 12.7062047 * 0.1, 1e-6);

  EXPECT_EQ(data.series[1].group, "corridor_mono");
  ASSERT_EQ(data.series[1].points.size(), 1u);
  EXPECT_EQ(data.series[1].points[0].success.count, 1);
  EXPECT_FALSE(data.series[1].points[0].success.defined());

  const std::string csv = success_csv(data);
  EXPECT_TRUE(contains(csv, "group,value,runs,mean,ci_low,ci_high\n")) << csv;
  // 0.4 -/+ 0.497 and 0.6 -/+ 1.27: clipped to the rates a run can have.
  EXPECT_TRUE(contains(csv, "corridor_pc,5000,3,0.4,0,0.896828\n")) << csv;
  EXPECT_TRUE(contains(csv, "corridor_pc,20000,2,0.6,0,1\n")) << csv;
  EXPECT_TRUE(contains(csv, "corridor_mono,20000,1,1,,\n")) << csv;
}

TEST(ReproductionFigures, OtherAxesSplitGroupsAndTheExperimentIsACategoricalAxis) {
  std::vector<RunSummary> runs = updates_sweep();
  runs[0].axes["policy.type"] = "monolithic";
  const SuccessByParameter split = success_by_parameter(runs, "policy.training.updates");
  ASSERT_EQ(split.series.size(), 3u);
  EXPECT_EQ(split.series[0].group, "corridor_pc, policy.type=monolithic");

  const std::vector<RunSummary> seeds_only = {run_of(1, "corridor_pc", {{"seed", "0"}}, 1.0),
                                              run_of(2, "corridor_mono", {{"seed", "0"}}, 0.5),
                                              run_of(3, "corridor_pc", {{"seed", "1"}}, 0.5)};
  const SuccessByParameter per_experiment = success_by_parameter(seeds_only, "experiment");
  EXPECT_FALSE(per_experiment.numeric);
  EXPECT_EQ(per_experiment.values, (std::vector<std::string>{"corridor_pc", "corridor_mono"}));
  ASSERT_EQ(per_experiment.series.size(), 1u);
  EXPECT_EQ(per_experiment.series[0].group, "");
  ASSERT_EQ(per_experiment.series[0].points.size(), 2u);
  EXPECT_EQ(per_experiment.series[0].points[0].x, 0.0);
  EXPECT_NEAR(per_experiment.series[0].points[0].success.mean, 0.75, 1e-12);
  EXPECT_EQ(per_experiment.series[0].points[1].x, 1.0);

  EXPECT_TRUE(success_by_parameter(seeds_only, "no.such.key").series.empty());
}

TEST(ReproductionFigures, OnlyNumericNonSeedAxesWithTwoValuesAreSwept) {
  std::vector<RunSummary> runs = updates_sweep();
  for (auto& run : runs) {
    run.axes["demonstrations.train"] = "20";                      // one value
    run.axes["policy.type"] = run.id % 2 ? "a" : "b";             // not numeric
    run.axes["environment.noise.seed"] = std::to_string(run.id);  // a seed
  }
  EXPECT_EQ(swept_numeric_axes(runs), (std::vector<std::string>{"policy.training.updates"}));
  EXPECT_TRUE(is_seed_key("seed"));
  EXPECT_TRUE(is_seed_key("evaluation.seed"));
  EXPECT_FALSE(is_seed_key("seeds"));
  EXPECT_FALSE(is_seed_key("policy.training.updates"));
}

TEST(ReproductionFigures, TheFirstSeedsRunIsTheLowestSeedThenTheLowestId) {
  const std::vector<RunSummary> runs = {run_of(5, "corridor_pc", {{"seed", "2"}}, 1.0),
                                        run_of(7, "corridor_pc", {{"seed", "0"}}, 1.0),
                                        run_of(6, "corridor_pc", {{"seed", "0"}}, 1.0),
                                        run_of(1, "corridor_ae", {{"seed", "9"}}, 1.0)};
  ASSERT_NE(first_seed_run(runs, "corridor_pc"), nullptr);
  EXPECT_EQ(first_seed_run(runs, "corridor_pc")->id, 6);
  EXPECT_EQ(first_seed_run(runs, "corridor_ae")->id, 1);
  EXPECT_EQ(first_seed_run(runs, "rope_color"), nullptr);
}

TEST(ReproductionFigures, SuccessChartsAreWrittenAtTheChartsSize) {
  TempDir dir;
  write_success_figure(success_by_parameter(updates_sweep(), "policy.training.updates"),
                       dir.file("s.png"));
  EXPECT_EQ(png_size(dir.file("s.png")), cv::Size(kIntervalChartWidth, kIntervalChartHeight));

  FigureSet set;
  add_success_figures(set, updates_sweep(), dir.path().string());
  ASSERT_EQ(set.figures.size(), 1u);
  EXPECT_EQ(set.figures[0].path, "figures/success_vs_policy_training_updates.png");
  EXPECT_TRUE(contains(set.figures[0].caption, "1 run without a task success rate"))
      << set.figures[0].caption;
  EXPECT_EQ(png_size(dir.file(set.figures[0].path)),
            cv::Size(kIntervalChartWidth, kIntervalChartHeight));
}

const TrajectoryView kCorridorView{
    "y", "x", "cor", {"push", "none", "pull"}, {"pre", "cor", "post"}, 100.0, "cm"};

TEST(ReproductionFigures, GroundTruthAgainstPredictionHasAColumnPerExpectedCorrection) {
  TempDir dir;
  write_trajectories(dir, "run1");
  const RunSummary run = run_of(1, "corridor_pc", {{"seed", "0"}}, 1.0);
  FigureSet set;
  add_trajectory_comparison(set, run, files_in(dir, "run1"), kCorridorView, dir.file("report"),
                            "gt");
  EXPECT_TRUE(set.notes.empty());
  ASSERT_EQ(set.figures.size(), 1u);
  EXPECT_EQ(set.figures[0].path, "figures/gt.png");
  const std::string& caption = set.figures[0].caption;
  EXPECT_TRUE(contains(caption, "corridor_pc run 1 (seed 0)")) << caption;
  EXPECT_TRUE(contains(caption, "push: trial 0, chose push, succeeded")) << caption;
  EXPECT_TRUE(contains(caption, "pull: trial 1, chose push, failed")) << caption;
  EXPECT_TRUE(contains(caption, "No trial of this run had the expected correction 'none'."))
      << caption;
  // A file written before executions were recorded: two curves, and the caption says why.
  EXPECT_TRUE(contains(caption,
                       "The paper's third curve, the executed motion, is not drawn: "
                       "this trajectories.csv has no executed columns"))
      << caption;
  EXPECT_FALSE(contains(caption, "(execution, thin black)")) << caption;
  // Two columns (push, pull), two rows (the whole skill, the cor segment).
  EXPECT_EQ(
      png_size(dir.file("report/figures/gt.png")),
      cv::Size(2 * kTrajectoryComparisonPanel, kLineFigureHeader + 2 * kTrajectoryComparisonPanel));
}

// The near-black pixels of the figure at `path` in its two rows of panels (below the
// heading and legend, whose height grows with the legend's rows).
int dark_pixels_in_panels(const std::string& path) {
  const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  int dark = 0;
  for (int y = image.rows - 2 * kTrajectoryComparisonPanel; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const cv::Vec3b p = image.at<cv::Vec3b>(y, x);
      dark += p[0] < 60 && p[1] < 60 && p[2] < 60;
    }
  }
  return dark;
}

TEST(ReproductionFigures, ExecutedColumnsAddTheExecutionCurveAndTheCaptionNamesAllThree) {
  TempDir dir;
  write_trajectories(dir, "old");
  write_trajectories(dir, "empty", testing::ExecutedColumns::empty);
  write_trajectories(dir, "new", testing::ExecutedColumns::values);
  const RunSummary run = run_of(1, "corridor_pc", {{"seed", "0"}}, 1.0);
  FigureSet set;
  for (const char* name : {"old", "empty", "new"}) {
    add_trajectory_comparison(set, run, files_in(dir, name), kCorridorView, dir.file("report"),
                              name);
  }
  ASSERT_TRUE(set.notes.empty()) << set.notes[0];
  ASSERT_EQ(set.figures.size(), 3u);
  const std::string& empty = set.figures[1].caption;
  EXPECT_TRUE(contains(empty,
                       "the executed motion, is not drawn: the task recorded no executed "
                       "path for these trials"))
      << empty;
  const std::string& drawn = set.figures[2].caption;
  EXPECT_TRUE(contains(drawn, "Ground truth vs prediction vs execution, corridor_pc run 1"))
      << drawn;
  EXPECT_TRUE(contains(drawn,
                       "(ground truth, grey dashed), the trajectory the policy generated "
                       "(prediction, coloured by segment) and the path the effectors "
                       "executed following it (execution, thin black)"))
      << drawn;
  EXPECT_FALSE(contains(drawn, "not drawn")) << drawn;
  // The same panels, with a thin black line along each of the 2 x 2 panels' paths.
  const int without = dark_pixels_in_panels(dir.file("report/figures/old.png"));
  EXPECT_EQ(dark_pixels_in_panels(dir.file("report/figures/empty.png")), without);
  const int with = dark_pixels_in_panels(dir.file("report/figures/new.png"));
  EXPECT_GT(with - without, 4 * kTrajectoryComparisonPanel / 2) << without << " -> " << with;
  // The legend's "execution" entry takes a second row.
  EXPECT_EQ(png_size(dir.file("report/figures/new.png")),
            png_size(dir.file("report/figures/old.png")) + cv::Size(0, kLegendRowHeight));
}

TEST(ReproductionFigures, OneExpectedCorrectionPutsItsTwoPanelsSideBySide) {
  TempDir dir;
  write_trajectories(dir, "run1");
  RunFiles files = files_in(dir, "run1");
  files.trials = {{1, "pull", "pull", true}};
  FigureSet set;
  add_trajectory_comparison(set, run_of(1, "corridor_pc", {{"seed", "0"}}, 1.0), files,
                            kCorridorView, dir.file("report"), "gt");
  ASSERT_EQ(set.figures.size(), 1u);
  EXPECT_TRUE(contains(set.figures[0].caption,
                       "No trial of this run had the expected correction 'push', 'none'."));
  EXPECT_EQ(
      png_size(dir.file("report/figures/gt.png")),
      cv::Size(2 * kTrajectoryComparisonPanel, kLineFigureHeader + kTrajectoryComparisonPanel));
}

TEST(ReproductionFigures, MissingRunDirectoriesAndFilesAreNotedNotFatal) {
  TempDir dir;
  const RunSummary run = run_of(4, "corridor_ae", {{"seed", "0"}}, 1.0);
  FigureSet set;
  RunFiles none;
  add_trajectory_comparison(set, run, none, kCorridorView, dir.file("report"), "a");
  RunFiles gone;
  gone.recorded = "/nonexistent/corridor_ae/4";
  add_trajectory_comparison(set, run, gone, kCorridorView, dir.file("report"), "b");
  dir.write("empty/placeholder", "");
  add_trajectory_comparison(set, run, files_in(dir, "empty"), kCorridorView, dir.file("report"),
                            "c");
  add_copied_figure(set, run, files_in(dir, "empty"), "autoencoder_reconstructions.png",
                    dir.file("report"), "d", "caption");
  EXPECT_TRUE(set.figures.empty());
  ASSERT_EQ(set.notes.size(), 4u);
  EXPECT_TRUE(contains(set.notes[0], "corridor_ae run 4 (seed 0) records no run directory"))
      << set.notes[0];
  EXPECT_TRUE(contains(set.notes[1], "'/nonexistent/corridor_ae/4'")) << set.notes[1];
  EXPECT_TRUE(contains(set.notes[2], "trajectories.csv")) << set.notes[2];
  EXPECT_TRUE(contains(set.notes[3], "autoencoder_reconstructions.png")) << set.notes[3];
  EXPECT_FALSE(fs::exists(dir.file("report/figures/a.png")));

  // The report lists the notes under its figures.
  const std::string section = figures_section(set.figures, set.notes);
  EXPECT_TRUE(contains(section, "No figures listed.")) << section;
  EXPECT_TRUE(contains(section, "Skipped:\n\n- ground truth vs prediction (corridor_ae)"))
      << section;
}

TEST(ReproductionFigures, TrainingCurvesAreReadPerNetworkWithEmptyValidationAsNaN) {
  TempDir dir;
  const std::string path =
      dir.write("curves.csv",
                "network,update,loss,validation_error_mean,validation_error_max\n"
                "pre,100,1.5,0.2,0.3\ncor,100,2.5,,\npre,200,0.5,0.1,0.2\n");
  const auto curves = read_training_curves(path);
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_EQ(curves[0].network, "pre");
  EXPECT_EQ(curves[0].updates, (std::vector<double>{100, 200}));
  EXPECT_EQ(curves[0].loss, (std::vector<double>{1.5, 0.5}));
  EXPECT_EQ(curves[1].network, "cor");
  EXPECT_TRUE(std::isnan(curves[1].validation_mean[0]));
  EXPECT_THROW(read_training_curves(dir.write("bad.csv", "network,step\n")), std::runtime_error);
  EXPECT_THROW(read_training_curves(dir.file("absent.csv")), std::runtime_error);
}

TEST(ReproductionFigures, TrainingCurvesSkipRunsWithoutTheFile) {
  TempDir dir;
  const std::string csv =
      "network,update,loss,validation_error_mean,validation_error_max\n"
      "pre,100,1.5,0.2,0.3\npre,200,0.5,0.1,0.2\ncor,100,2.5,0.3,0.4\ncor,200,1.0,0.2,0.3\n";
  dir.write("run1/training_curves.csv", csv);
  dir.write("run3/training_curves.csv", csv);
  dir.write("run2/log.txt", "");  // a run older than training_curves.csv
  const std::vector<RunSummary> runs = {run_of(1, "corridor_pc", {{"seed", "0"}}, 1.0),
                                        run_of(2, "corridor_pc", {{"seed", "1"}}, 1.0),
                                        run_of(3, "corridor_pc", {{"seed", "2"}}, 1.0)};
  RunFilesById files;
  for (const auto& run : runs) files[run.id] = files_in(dir, "run" + std::to_string(run.id));
  FigureSet set;
  add_training_curves(set, "corridor_pc", {&runs[0], &runs[1], &runs[2]}, files,
                      dir.file("report"));
  ASSERT_EQ(set.notes.size(), 1u);
  EXPECT_TRUE(contains(set.notes[0], "corridor_pc run 2 (seed 1) has no training_curves.csv"))
      << set.notes[0];
  ASSERT_EQ(set.figures.size(), 1u);
  EXPECT_EQ(set.figures[0].path, "figures/training_curves_corridor_pc.png");
  EXPECT_TRUE(contains(set.figures[0].caption, "their mean in black")) << set.figures[0].caption;
  // Two networks: loss and validation panels of 320 x 240 in two rows.
  EXPECT_EQ(png_size(dir.file("report/figures/training_curves_corridor_pc.png")),
            cv::Size(2 * 320, kLineFigureHeader + 2 * 240));

  FigureSet nothing;
  add_training_curves(nothing, "corridor_pc", {&runs[1]}, files, dir.file("report"));
  EXPECT_TRUE(nothing.figures.empty());
  EXPECT_TRUE(any_note(nothing, "skipped, no run has training curves"));
}

TEST(ReproductionFigures, RunFilesComeFromTheStoreWithRelativeDirectoriesFound) {
  TempDir dir;
  dir.write("results/runs/7/log.txt", "");
  ResultStore store(dir.file("results/r.sqlite"));
  testing::RunSpec spec;
  spec.experiment = "corridor_pc";
  spec.trials = {{"push", "push", true}, {"pull", "none", false}};
  const int64_t relative = testing::record_run(store, spec);
  const int64_t absolute = testing::record_run(store, spec);
  const int64_t missing = testing::record_run(store, spec);
  const int64_t unset = testing::record_run(store, spec);
  // A path relative to the database's folder's parent, as `--out results`
  // from the project's root records it.
  store.set_out_dir(relative, "results/runs/7");
  store.set_out_dir(absolute, dir.file("results/runs/7"));
  store.set_out_dir(missing, "results/runs/404");
  const auto runs = load_run_summaries(store, ReportQuery{});
  const RunFilesById files = load_run_files(store, runs);
  ASSERT_EQ(files.size(), 4u);
  EXPECT_TRUE(fs::equivalent(files.at(relative).directory, dir.file("results/runs/7")));
  EXPECT_EQ(files.at(absolute).directory, dir.file("results/runs/7"));
  EXPECT_EQ(files.at(missing).recorded, "results/runs/404");
  EXPECT_EQ(files.at(missing).directory, "");
  EXPECT_EQ(files.at(unset).recorded, "");
  const auto& trials = files.at(relative).trials;
  ASSERT_EQ(trials.size(), 2u);
  EXPECT_EQ(trials[1].trial, 1);
  EXPECT_EQ(trials[1].expected, "pull");
  EXPECT_EQ(trials[1].chosen, "none");
  EXPECT_FALSE(trials[1].success);
  EXPECT_TRUE(trials[0].success);
}

}  // namespace
}  // namespace corrmp
