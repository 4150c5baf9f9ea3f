// Tests of the report tool's figures: --plot-success writes the chart and its
// numbers, refuses a setting no run has in one line, and --reproduction lists
// its figures with notes for runs whose directories are missing.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "config/test_files.hpp"
#include "plot/interval_chart.hpp"
#include "support/recorded_runs.hpp"
#include "support/report_tool.hpp"

namespace corrmp {
namespace {

using testing::read;
using testing::report_tool;
using testing::RunSpec;
using testing::TempDir;
using testing::ToolOutcome;

// Sweep "s1" over seeds: corridor_pc (4 and 3 of 4 trials) and corridor_mono
// (1 and 2 of 4); no run records a directory.
void record_figure_runs(const TempDir& dir) {
  ResultStore store(dir.file("r.sqlite"));
  testing::add_sweep(store, "s1", "paper", 4);
  int job = 0;
  for (const auto& [experiment, successes] : std::vector<std::pair<std::string, int>>{
           {"corridor_pc", 4}, {"corridor_pc", 3}, {"corridor_mono", 1}, {"corridor_mono", 2}}) {
    RunSpec spec;
    spec.experiment = experiment;
    spec.sweep_id = "s1";
    spec.job_index = job;
    spec.axes = "{\"seed\":\"" + std::to_string(job++) + "\"}";
    spec.trials = testing::trials_of("push", 4, successes);
    spec.metrics = {{"task_success_rate", successes / 4.0}};
    testing::record_run(store, spec);
  }
}

TEST(ReportFiguresTool, PlotsSuccessPerExperimentWithItsNumbers) {
  TempDir dir;
  record_figure_runs(dir);
  const ToolOutcome plotted =
      report_tool(dir, "--plot-success experiment --sweep s1 --out " + dir.file("plots"));
  ASSERT_EQ(plotted.exit_code, 0) << plotted.err;
  EXPECT_EQ(plotted.out,
            "report: wrote " + dir.file("plots/success_vs_experiment") + ".png and .csv\n");
  const cv::Mat chart = cv::imread(dir.file("plots/success_vs_experiment.png"));
  EXPECT_EQ(chart.size(), cv::Size(kIntervalChartWidth, kIntervalChartHeight));
  const std::string csv = read(dir.file("plots/success_vs_experiment.csv"));
  // 0.875 -/+ 1.588 across the two seeds: the interval clipped to [0, 1].
  EXPECT_NE(csv.find(",corridor_pc,2,0.875,0,1\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",corridor_mono,2,0.375,"), std::string::npos) << csv;
}

TEST(ReportFiguresTool, RefusesASettingNoRunHasAndAPlotWithoutAFolder) {
  TempDir dir;
  record_figure_runs(dir);
  const ToolOutcome unknown =
      report_tool(dir, "--plot-success policy.nope --sweep s1 --out " + dir.file("plots"));
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.err,
            "report: no selected run has both a task success rate and a setting 'policy.nope'\n");
  const ToolOutcome no_out = report_tool(dir, "--plot-success experiment --sweep s1");
  EXPECT_EQ(no_out.exit_code, 2);
  EXPECT_EQ(no_out.err, "report: --plot-success needs --out DIR\n");
}

TEST(ReportFiguresTool, TheReproductionListsItsFiguresAndWhatIsMissing) {
  TempDir dir;
  record_figure_runs(dir);
  const ToolOutcome written =
      report_tool(dir, "--reproduction --sweep s1 --out " + dir.file("reproduction"));
  ASSERT_EQ(written.exit_code, 0) << written.err;
  const std::string md = read(dir.file("reproduction/report.md"));
  EXPECT_NE(md.find("](figures/success_vs_experiment.png)"), std::string::npos) << md;
  EXPECT_TRUE(std::filesystem::exists(dir.file("reproduction/figures/success_vs_experiment.png")));
  EXPECT_NE(md.find("Skipped:\n\n- ground truth vs prediction (corridor_pc): skipped, "
                    "corridor_pc run 1 (seed 0) records no run directory"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("- training curves (corridor_mono): skipped, no run has training curves"),
            std::string::npos)
      << md;
}

}  // namespace
}  // namespace corrmp
