// Tests of run comparisons: groups by experiment or by setting and sweep axis,
// means with 95% Student t intervals across seeds, pooled success with Wilson
// intervals, Fisher's exact test on the pooled trials and Welch's interval for
// the difference of means, in Markdown and CSV; and the report tool's
// --compare and its usage errors. Reference numbers from mpmath and R.
#include "report/run_comparison.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "config/test_files.hpp"
#include "support/recorded_runs.hpp"

namespace corrmp {
namespace {

using testing::RunSpec;
using ::testing::StrEq;
using testing::TempDir;
using ::testing::ThrowsMessage;
using testing::trials_of;

RunSpec corridor_run(const std::string& experiment, int successes, double cor_error) {
  RunSpec spec;
  spec.experiment = experiment;
  spec.trials = trials_of("push", 4, successes);
  spec.metrics = {{"task_success_rate", successes / 4.0},
                  {"decision_match_rate", 1.0},
                  {"cor_mp_error_mean_cm", cor_error},
                  {"cor_mp_error_max_cm", 2 * cor_error},
                  {"autoencoder_train_mse", 0.01}};
  return spec;
}

// corridor_pc: 4, 3, 4 of 4 (11 of 12); corridor_mono: 2, 1, 2 of 4 (5 of 12).
void record_pc_and_mono(ResultStore& store) {
  for (int successes : {4, 3, 4})
    testing::record_run(store, corridor_run("corridor_pc", successes, 0.8));
  for (int successes : {2, 1, 2}) {
    testing::record_run(store, corridor_run("corridor_mono", successes, 1.3));
  }
}

// The CSV's rows as fields (the test's names hold no commas or quotes).
std::vector<std::vector<std::string>> csv_rows(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream lines(csv);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) fields.push_back(cell);
    if (!line.empty() && line.back() == ',') fields.push_back("");
    rows.push_back(fields);
  }
  return rows;
}

// The CSV row of this kind, group and metric, by column name.
std::map<std::string, std::string> csv_row(const std::string& csv, const std::string& kind,
                                           const std::string& group, const std::string& metric) {
  const auto rows = csv_rows(csv);
  for (size_t r = 1; r < rows.size(); ++r) {
    if (rows[r][0] == kind && rows[r][1] == group && rows[r][3] == metric) {
      std::map<std::string, std::string> row;
      for (size_t c = 0; c < rows[0].size(); ++c) row[rows[0][c]] = rows[r].at(c);
      return row;
    }
  }
  ADD_FAILURE() << "no row " << kind << "," << group << ",," << metric << " in\n" << csv;
  return {};
}

TEST(RunComparison, GroupsByExperimentWithIntervalsAcrossSeeds) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_pc_and_mono(store);
  const RunComparison c = compare_runs(load_run_summaries(store, {}), {});
  EXPECT_EQ(c.grouping, "experiment");
  ASSERT_EQ(c.groups.size(), 2u);
  EXPECT_EQ(c.groups[0].name, "corridor_pc");
  EXPECT_EQ(c.groups[0].runs, (std::vector<int64_t>{1, 2, 3}));
  EXPECT_EQ(c.groups[0].trials, 12);
  EXPECT_EQ(c.metrics, (std::vector<std::string>{"task_success_rate", "decision_match_rate",
                                                 "cor_mp_error_mean_cm", "cor_mp_error_max_cm"}));
  const MeanInterval& success = c.groups[0].metrics.at("task_success_rate");
  EXPECT_NEAR(success.mean, 11.0 / 12.0, 1e-12);
  EXPECT_NEAR(success.half_width, 0.3585543941457885, 1e-10);  // t(0.975, 2) s / sqrt(3)
  EXPECT_EQ(c.groups[0].pooled_success.successes, 11);
  EXPECT_NEAR(c.groups[0].pooled_success.low, 0.6461200888588832, 1e-10);

  ASSERT_EQ(c.differences.size(), 1u);
  const SuccessDifference& d = c.differences[0];
  EXPECT_EQ(d.group, "corridor_pc");
  EXPECT_EQ(d.versus, "corridor_mono");
  EXPECT_NEAR(d.pooled_difference, 0.5, 1e-12);
  EXPECT_NEAR(d.fisher_p, 0.027190738995827163, 1e-12);  // fisher.test on [[11, 1], [5, 7]]
  EXPECT_NEAR(d.across_seeds.difference, 0.5, 1e-12);
  EXPECT_NEAR(d.across_seeds.half_width, 0.3272071935795928, 1e-10);  // Welch, 4 dof

  const std::string md = comparison_markdown(c);
  EXPECT_NE(md.find("Grouped by experiment: 2 groups, 6 runs."), std::string::npos) << md;
  // The interval 0.558 to 1.275 of a rate is printed clipped to 1.
  EXPECT_NE(md.find("| corridor_pc | 3 | 12 | 11 of 12 (91.7%, 95% CI 64.6-98.5%) | 0.917 "
                    "[0.558, 1.000] | 1.000 [1.000, 1.000] | 0.800 [0.800, 0.800] | 1.600 "
                    "[1.600, 1.600] |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("clipped to the values the metric can take: rates to [0, 1]"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("Fisher's exact test, two-sided"), std::string::npos) << md;
  EXPECT_NE(md.find("pooled across each group's runs (seeds)"), std::string::npos) << md;
  EXPECT_NE(md.find("| corridor_pc | corridor_mono | 11 of 12 (91.7%) | 5 of 12 (41.7%) | +50.0 "
                    "pp | 0.02719 | +0.500 [0.173, 0.827] |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("Runs: corridor_pc: 1, 2, 3. corridor_mono: 4, 5, 6."), std::string::npos)
      << md;

  const std::string csv = comparison_csv(c);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "kind,group,versus,metric,runs,trials,successes,mean,ci_low,ci_high,versus_trials,"
            "versus_successes,fisher_p");
  auto mono = csv_row(csv, "mean", "corridor_mono", "task_success_rate");
  EXPECT_EQ(mono["runs"], "3");
  EXPECT_NEAR(std::stod(mono["mean"]), 5.0 / 12.0, 1e-12);
  EXPECT_NEAR(std::stod(mono["ci_low"]), 0.058112272520878194, 1e-10);
  EXPECT_NEAR(std::stod(mono["ci_high"]), 0.7752210608124552, 1e-10);
  auto pc = csv_row(csv, "mean", "corridor_pc", "task_success_rate");
  EXPECT_NEAR(std::stod(pc["mean"]), 11.0 / 12.0, 1e-12);  // the mean is not clipped
  EXPECT_NEAR(std::stod(pc["ci_low"]), 0.5581122725208781, 1e-10);
  EXPECT_EQ(pc["ci_high"], "1");  // 1.275 clipped
  auto pooled = csv_row(csv, "pooled_success", "corridor_mono", "task_success");
  EXPECT_EQ(pooled["successes"], "5");
  EXPECT_NEAR(std::stod(pooled["ci_high"]), 0.6804886874504503, 1e-10);
  auto difference = csv_row(csv, "difference", "corridor_pc", "task_success_rate");
  EXPECT_EQ(difference["versus"], "corridor_mono");
  EXPECT_EQ(difference["versus_successes"], "5");
  EXPECT_NEAR(std::stod(difference["fisher_p"]), 0.027190738995827163, 1e-12);
  EXPECT_NEAR(std::stod(difference["ci_low"]), 0.5 - 0.3272071935795928, 1e-10);
}

// Runs with no environment (curves_demo) have no trials but record the held-out
// demonstrations' errors: those are compared, small ones with three significant digits.
TEST(RunComparison, ComparesTheHeldOutErrorsOfRunsWithoutAnEnvironment) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  for (const double error : {0.004, 0.005, 0.006}) {
    RunSpec spec;
    spec.experiment = "curves_demo";
    spec.metrics = {{"full_error_mean", error}, {"full_error_max", 4 * error}};
    testing::record_run(store, spec);
  }
  const RunComparison c = compare_runs(load_run_summaries(store, {}), {});
  EXPECT_EQ(c.metrics,
            (std::vector<std::string>{"task_success_rate", "full_error_mean", "full_error_max"}));
  const std::string md = comparison_markdown(c);
  // 0.005 +- t(0.975, 2) 0.001 / sqrt(3) = 0.005 +- 0.00248
  EXPECT_NE(md.find("| 0.00500 [0.00252, 0.00748] | 0.0200 [0.0101, 0.0299] |"), std::string::npos)
      << md;
}

TEST(RunComparison, ComparesEveryPairOrEachGroupWithTheBaseline) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_pc_and_mono(store);
  testing::record_run(store, corridor_run("corridor_ae", 4, 0.8));
  const auto runs = load_run_summaries(store, {});
  const RunComparison pairs = compare_runs(runs, {});
  ASSERT_EQ(pairs.differences.size(), 3u);
  EXPECT_EQ(pairs.differences[2].group, "corridor_mono");
  EXPECT_EQ(pairs.differences[2].versus, "corridor_ae");

  ComparisonOptions options;
  options.baseline = "corridor_mono";
  const RunComparison baseline = compare_runs(runs, options);
  ASSERT_EQ(baseline.differences.size(), 2u);
  EXPECT_EQ(baseline.differences[0].group, "corridor_pc");
  EXPECT_EQ(baseline.differences[1].group, "corridor_ae");
  for (const auto& d : baseline.differences) EXPECT_EQ(d.versus, "corridor_mono");
  // corridor_ae has one run: no interval for it or for its difference of means.
  const std::string md = comparison_markdown(baseline);
  EXPECT_NE(md.find("| corridor_ae | 1 | 4 | 4 of 4 (100.0%, 95% CI 51.0-100.0%) | 1.000 (1 run, "
                    "no interval) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| +0.583 (a group has 1 run, no interval) |"), std::string::npos) << md;
  const auto row = csv_row(comparison_csv(baseline), "mean", "corridor_ae", "task_success_rate");
  EXPECT_EQ(row.at("ci_low"), "");
  EXPECT_EQ(row.at("mean"), "1");
}

TEST(RunComparison, GroupsBySweepAxesAndSettings) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  testing::add_sweep(store, "s1", "policies", 4);
  int job = 0;
  for (const auto& [policy, successes] :
       std::vector<std::pair<std::string, int>>{{"segmented_cnmp", 4},
                                                {"segmented_cnmp", 4},
                                                {"monolithic_cnmp", 1},
                                                {"monolithic_cnmp", 2}}) {
    RunSpec spec = corridor_run("corridor", successes, 1.0);
    spec.config = "seed: " + std::to_string(job) + "\npolicy: {type: " + policy + "}\n";
    spec.sweep_id = "s1";
    spec.job_index = job++;
    spec.axes = "{\"seed\":\"" + std::to_string(job) + "\",\"policy.type\":\"" + policy + "\"}";
    testing::record_run(store, spec);
  }
  testing::record_run(store, corridor_run("corridor", 0, 1.0));  // outside the sweep

  ReportQuery query;
  query.sweeps = {"s1"};
  const auto runs = load_run_summaries(store, query);
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs[2].axes.at("policy.type"), "monolithic_cnmp");
  EXPECT_EQ(runs[2].axes.at("seed"), "3");  // the axis value as written, not the config's 2

  ComparisonOptions by_policy;
  by_policy.group_by = {"policy.type"};
  const RunComparison c = compare_runs(runs, by_policy);
  EXPECT_EQ(c.grouping, "policy.type");
  ASSERT_EQ(c.groups.size(), 2u);
  EXPECT_EQ(c.groups[0].name, "policy.type=segmented_cnmp");
  EXPECT_EQ(c.groups[1].name, "policy.type=monolithic_cnmp");
  EXPECT_EQ(c.groups[1].pooled_success.successes, 3);
  EXPECT_NEAR(c.differences[0].fisher_p, 1.0 / 39.0, 1e-12);  // 8 of 8 against 3 of 8

  // A key only some runs have leaves the others "(unset)".
  auto noted = runs;
  noted[0].settings["note"] = "x";
  ComparisonOptions by_two;
  by_two.group_by = {"experiment", "note"};
  const RunComparison unset = compare_runs(noted, by_two);
  ASSERT_EQ(unset.groups.size(), 2u);
  EXPECT_EQ(unset.groups[0].name, "experiment=corridor, note=x");
  EXPECT_EQ(unset.groups[1].name, "experiment=corridor, note=(unset)");
}

// The error compare_runs throws, or "" when it throws none.
std::string comparison_error(const std::vector<RunSummary>& runs,
                             const std::vector<std::string>& group_by) {
  ComparisonOptions options;
  options.group_by = group_by;
  try {
    compare_runs(runs, options);
  } catch (const ComparisonError& e) {
    return e.what();
  }
  return "";
}

// A --by key no selected run has would put every run in one "(unset)" group,
// averaging all of them as if they were seeds: refused, with a close key when
// there is one.
TEST(RunComparison, RefusesAGroupingKeyNoRunHas) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  for (int seed : {0, 1}) {
    RunSpec spec = corridor_run("corridor_pc", 3, 1.0);
    spec.config = "seed: " + std::to_string(seed) + "\npolicy: {type: segmented_cnmp}\n";
    testing::record_run(store, spec);
  }
  const auto runs = load_run_summaries(store, {});
  EXPECT_EQ(comparison_error(runs, {"nosuch.key"}),
            "--by 'nosuch.key': no selected run has this setting");
  EXPECT_EQ(comparison_error(runs, {"experiment", "policy.typ"}),
            "--by 'policy.typ': no selected run has this setting (did you mean 'policy.type'?)");
  EXPECT_EQ(comparison_error(runs, {"type"}),
            "--by 'type': no selected run has this setting (did you mean 'policy.type'?)");
  EXPECT_EQ(comparison_error(runs, {"policy.type", "experiment"}), "");
}

RunSummary summary_of(int64_t id, const std::string& experiment,
                      const std::map<std::string, std::string>& axes, double success) {
  RunSummary run;
  run.id = id;
  run.experiment = experiment;
  run.axes = axes;
  run.settings = axes;  // an axis is a config key
  run.settings["evaluation.trials"] = "4";
  run.trials = 4;
  run.successes = static_cast<int>(4 * success);
  run.metrics = {{"task_success_rate", success}};
  run.metric_order = {"task_success_rate"};
  testing::declare_as_migrated(run);
  return run;
}

// Intervals are clipped to the values a metric can take (rates [0, 1],
// errors from 0, differences of rates [-1, 1]); other metrics and the means
// are not.
TEST(RunComparison, ClipsIntervalsToTheValuesAMetricCanTake) {
  std::vector<RunSummary> runs = {
      summary_of(1, "a", {{"seed", "0"}}, 1.0), summary_of(2, "a", {{"seed", "1"}}, 0.25),
      summary_of(3, "b", {{"seed", "0"}}, 0.0), summary_of(4, "b", {{"seed", "1"}}, 0.75)};
  const std::vector<std::pair<double, double>> values = {{0.1, -1.0}, {3.0, 1.0}};
  for (size_t i = 0; i < runs.size(); ++i) {
    runs[i].metrics["cor_mp_error_mean_cm"] = values[i % 2].first;
    runs[i].metrics["offset_x"] = values[i % 2].second;
    runs[i].metric_order.push_back("cor_mp_error_mean_cm");
    testing::declare_as_migrated(runs[i]);
  }
  ComparisonOptions options;
  options.extra_metrics = {"offset_x"};
  const RunComparison c = compare_runs(runs, options);
  EXPECT_NEAR(c.groups[0].metrics.at("task_success_rate").low, -4.139826776075, 1e-9);

  const std::string csv = comparison_csv(c);
  auto success = csv_row(csv, "mean", "a", "task_success_rate");
  EXPECT_EQ(success["mean"], "0.625");
  EXPECT_EQ(success["ci_low"], "0");
  EXPECT_EQ(success["ci_high"], "1");
  auto error = csv_row(csv, "mean", "a", "cor_mp_error_mean_cm");
  EXPECT_EQ(error["ci_low"], "0");  // -16.87 clipped
  EXPECT_NEAR(std::stod(error["ci_high"]), 19.97399686749, 1e-9);
  auto offset = csv_row(csv, "mean", "a", "offset_x");
  EXPECT_NEAR(std::stod(offset["ci_low"]), -12.7062047362, 1e-8);  // unbounded: as computed
  auto difference = csv_row(csv, "difference", "a", "task_success_rate");
  EXPECT_EQ(difference["mean"], "0.25");
  EXPECT_EQ(difference["ci_low"], "-1");
  EXPECT_EQ(difference["ci_high"], "1");

  const std::string md = comparison_markdown(c);
  EXPECT_NE(md.find("| a | 2 | 8 | 5 of 8 (62.5%, 95% CI 30.6-86.3%) | 0.625 [0.000, 1.000] | "
                    "1.550 [0.000, 19.974] | 0.000 [-12.706, 12.706] |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| +0.250 [-1.000, 1.000] |"), std::string::npos) << md;
  EXPECT_NE(md.find("Welch t interval clipped to [-1, 1]"), std::string::npos) << md;
}

// Groups that pool more than seeds are named, with what they pool; the
// numbers stay those of the pooled runs.
TEST(RunComparison, NamesGroupsThatPoolMoreThanSeeds) {
  const std::vector<RunSummary> runs = {
      summary_of(1, "corridor_pc", {{"seed", "0"}, {"policy.training.updates", "100"}}, 1.0),
      summary_of(2, "corridor_pc", {{"seed", "1"}, {"policy.training.updates", "200"}}, 0.5),
      summary_of(3, "corridor_ae", {{"seed", "0"}, {"policy.training.updates", "100"}}, 0.75),
      summary_of(4, "corridor_ae", {{"seed", "1"}, {"policy.training.updates", "100"}}, 0.25)};

  // By experiment: corridor_pc's runs differ in the updates, corridor_ae's
  // only in the seed.
  const RunComparison by_experiment = compare_runs(runs, {});
  EXPECT_EQ(by_experiment.groups[0].experiments, std::vector<std::string>{"corridor_pc"});
  EXPECT_EQ(by_experiment.groups[0].differing, std::vector<std::string>{"policy.training.updates"});
  EXPECT_TRUE(by_experiment.groups[1].differing.empty());
  EXPECT_EQ(pooling_notes(by_experiment),
            std::vector<std::string>{
                "group corridor_pc pools runs that differ in policy.training.updates"});
  EXPECT_NEAR(by_experiment.groups[0].metrics.at("task_success_rate").mean, 0.75, 1e-12);
  const std::string md = comparison_markdown(by_experiment);
  EXPECT_NE(md.find("\n- group corridor_pc pools runs that differ in policy.training.updates\n"),
            std::string::npos)
      << md;

  // By the updates: the group at 100 pools both experiments; the one at 200
  // holds a single run.
  ComparisonOptions by_updates;
  by_updates.group_by = {"policy.training.updates"};
  const RunComparison pooled = compare_runs(runs, by_updates);
  ASSERT_EQ(pooled.groups.size(), 2u);
  EXPECT_EQ(pooled.groups[0].runs, (std::vector<int64_t>{1, 3, 4}));
  EXPECT_NEAR(pooled.groups[0].metrics.at("task_success_rate").mean, 2.0 / 3.0, 1e-12);
  EXPECT_EQ(pooling_notes(pooled),
            std::vector<std::string>{"group policy.training.updates=100 pools experiments "
                                     "corridor_pc, corridor_ae"});

  // Both at once; and nothing to say when the groups differ only in seeds.
  auto mixed = runs;
  mixed[3].settings["evaluation.trials"] = "8";
  EXPECT_EQ(pooling_notes(compare_runs(mixed, by_updates)),
            std::vector<std::string>{"group policy.training.updates=100 pools experiments "
                                     "corridor_pc, corridor_ae and runs that differ in "
                                     "evaluation.trials"});
  ComparisonOptions by_both;
  by_both.group_by = {"experiment", "policy.training.updates"};
  const RunComparison seeds_only = compare_runs(runs, by_both);
  EXPECT_TRUE(pooling_notes(seeds_only).empty());
  EXPECT_EQ(comparison_markdown(seeds_only).find("pools"), std::string::npos);
}

TEST(RunComparison, RefusesNoRunsAndAnUnknownBaseline) {
  EXPECT_THROW(compare_runs({}, {}), ComparisonError);
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_pc_and_mono(store);
  ComparisonOptions options;
  options.baseline = "corridor_ae";
  EXPECT_THAT([&] { compare_runs(load_run_summaries(store, {}), options); },
              ThrowsMessage<ComparisonError>(
                  StrEq("no group 'corridor_ae' to compare with (the groups: 'corridor_pc', "
                        "'corridor_mono')")));
}

}  // namespace
}  // namespace corrmp
