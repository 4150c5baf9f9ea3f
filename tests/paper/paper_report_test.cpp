// Tests of the paper-reproduction report: Tables I and II of the corridor
// experiments against assets/paper/tables.yaml with intervals across seeds and
// verdicts, the rope section, the figures, report.csv holding the same cells,
// and the errors. Reference intervals from mpmath (t(0.975, 2) = 4.302653).
#include "paper/paper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "config/test_files.hpp"
#include "support/recorded_runs.hpp"

namespace corrmp {
namespace {

using testing::RunSpec;
using testing::TempDir;
using testing::TrialSpec;

const ReproductionSpec& paper() {
  static const ReproductionSpec spec = load_paper(std::string(PROJECT_DIR) + "/assets/paper");
  return spec;
}

struct CorridorNumbers {
  double success, success_none, match_push, cor_mean, cor_max, post_mean, post_max;
};

RunSpec corridor_run(const std::string& experiment, int job, const CorridorNumbers& n,
                     const std::vector<TrialSpec>& trials) {
  RunSpec spec;
  spec.experiment = experiment;
  spec.config = "seed: " + std::to_string(job) + "\n";
  spec.sweep_id = "s1";
  spec.job_index = job;
  spec.axes = "{\"seed\":\"" + std::to_string(job) + "\"}";
  spec.trials = trials;
  spec.metrics = {{"task_success_rate", n.success},       {"decision_match_rate", 1.0},
                  {"cor_mp_error_mean_cm", n.cor_mean},   {"cor_mp_error_max_cm", n.cor_max},
                  {"post_mp_error_mean_cm", n.post_mean}, {"post_mp_error_max_cm", n.post_max}};
  for (const char* label : {"push", "none", "pull"}) {
    const std::string l = label;
    spec.metrics.push_back({"expected_" + l, l == "pull" ? 1.0 : 2.0});
    spec.metrics.push_back({"decision_match_rate_" + l, l == "push" ? n.match_push : 1.0});
    spec.metrics.push_back({"task_success_rate_" + l, l == "none" ? n.success_none : 1.0});
  }
  return spec;
}

// The sweep "s1": corridor_pc with 3 seeds, corridor_ae with 1, corridor_mono
// with 3, rope_color with 2, and a run of another experiment.
void record_sweep(ResultStore& store) {
  testing::add_sweep(store, "s1", "paper", 10);
  int job = 0;
  const std::vector<TrialSpec> clean = {{"push", "push", true},
                                        {"push", "push", true},
                                        {"none", "none", true},
                                        {"none", "none", true},
                                        {"pull", "pull", true}};
  std::vector<TrialSpec> one_none = clean;  // one push decided as none
  one_none[1].chosen = "none";
  std::vector<TrialSpec> failed_none = clean;
  failed_none[3].success = false;
  testing::record_run(
      store, corridor_run("corridor_pc", job++, {1.0, 1.0, 1.0, 0.8, 1.40, 3.0, 3.0}, clean));
  testing::record_run(
      store, corridor_run("corridor_pc", job++, {1.0, 1.0, 0.5, 0.9, 1.45, 3.1, 3.1}, one_none));
  testing::record_run(store, corridor_run("corridor_pc", job++,
                                          {0.75, 0.5, 1.0, 1.0, 1.50, 3.2, 3.2}, failed_none));
  testing::record_run(
      store, corridor_run("corridor_ae", job++, {1.0, 1.0, 1.0, 0.8, 1.0, 2.6, 4.8}, clean));
  for (double cor : {1.0, 1.01, 1.02}) {
    testing::record_run(
        store, corridor_run("corridor_mono", job++, {0.2, 0.5, 1.0, cor, 1.9, 5.7, 7.2}, clean));
  }
  for (double none : {1.0, 0.5}) {
    RunSpec rope;
    rope.experiment = "rope_color";
    rope.config = "seed: " + std::to_string(job) + "\n";
    rope.sweep_id = "s1";
    rope.job_index = job++;
    rope.trials = {{"none", "none", true},
                   {"none", "none", none == 1.0},
                   {"lateral", "lateral", none == 1.0},
                   {"lateral", "none", false}};
    rope.metrics = {{"task_success_rate", (none == 1.0 ? 3 : 1) / 4.0},
                    {"expected_none", 2},
                    {"task_success_rate_none", none},
                    {"expected_lateral", 2},
                    {"task_success_rate_lateral", none == 1.0 ? 0.5 : 0.0},
                    {"knot_rate", 0.5}};
    testing::record_run(store, rope);
  }
  RunSpec other;
  other.experiment = "curves_demo";
  other.sweep_id = "s1";
  other.job_index = job++;
  testing::record_run(store, other);
}

// report.csv's row of a cell, by column name.
std::map<std::string, std::string> cell(const std::string& csv, const std::string& table,
                                        const std::string& row, const std::string& group,
                                        const std::string& quantity) {
  std::stringstream lines(csv);
  std::string line;
  std::vector<std::string> header;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (char c : line) {  // quoted fields hold commas ("5 Push, 1 No Correction")
      if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted)
        fields.push_back(std::exchange(field, ""));
      else
        field += c;
    }
    fields.push_back(field);
    if (header.empty()) {
      header = fields;
      continue;
    }
    if (fields[0] == table && fields[1] == row && fields[2] == group && fields[3] == quantity) {
      std::map<std::string, std::string> out;
      for (size_t i = 0; i < header.size(); ++i) out[header[i]] = fields.at(i);
      return out;
    }
  }
  ADD_FAILURE() << "no cell " << table << "," << row << "," << group << "," << quantity;
  return {{"mean", "nan"}, {"ci_low", "nan"}, {"ci_high", "nan"}};
}

ReproductionReport sweep_report(ResultStore& store, std::vector<ReportFigure> figures = {}) {
  ReproductionInputs inputs;
  ReportQuery query;
  query.sweeps = {"s1"};
  inputs.runs = load_run_summaries(store, query);
  inputs.sweep = find_sweep(store, "s1");
  inputs.figures = std::move(figures);
  return reproduction_report(paper(), inputs);
}

TEST(PaperReport, TableOneHoldsMeansWithIntervalsBesideThePapersNumbers) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_sweep(store);
  const ReproductionReport report = sweep_report(store);

  // PC task success over all trials: 1, 1, 0.75 -> 0.917 -/+ 0.359, clipped
  // to 1; the paper's 24 of 25 lies inside.
  auto all = cell(report.csv, "table_1", "all", "corridor_pc", "task_success_rate");
  EXPECT_EQ(all["runs"], "3");
  EXPECT_NEAR(std::stod(all["mean"]), 11.0 / 12.0, 1e-12);
  EXPECT_NEAR(std::stod(all["ci_low"]), 0.5581122725208781, 1e-10);
  EXPECT_EQ(std::stod(all["ci_high"]), 1.0);
  EXPECT_EQ(all["paper"], "96%");
  EXPECT_EQ(all["verdict"], "reproduced");
  // No correction: 1, 1, 0.5 (83.3%) against the paper's 83% (5 of 6).
  auto none = cell(report.csv, "table_1", "none", "corridor_pc", "task_success_rate_none");
  EXPECT_NEAR(std::stod(none["ci_low"]), 0.11622454504175639, 1e-10);
  EXPECT_EQ(none["ours"], "83.3% [11.6, 100.0]");
  EXPECT_EQ(none["paper"], "83%");
  EXPECT_EQ(none["verdict"], "reproduced");
  // Mono succeeds in 20% of every seed's trials: below the paper's 17 of 25.
  auto mono = cell(report.csv, "table_1", "all", "corridor_mono", "task_success_rate");
  EXPECT_EQ(mono["ours"], "20.0% [20.0, 20.0]");
  EXPECT_EQ(mono["paper"], "68%");
  EXPECT_EQ(mono["verdict"], "worse");
  // The paper's AE decision match over all trials: 8 + 6 + 9 of 25.
  EXPECT_EQ(cell(report.csv, "table_1", "all", "corridor_ae", "decision_match_rate")["paper"],
            "92%");
  EXPECT_EQ(
      cell(report.csv, "table_1", "push", "corridor_ae", "decision_match_rate_push")["verdict"],
      "no interval (1 run)");
  // Action choice: the trials' chosen actions pooled over the runs.
  auto choice = cell(report.csv, "table_1", "push", "corridor_pc", "action_choice");
  EXPECT_EQ(choice["ours"], "5 Push, 1 No Correction (3 runs)");
  EXPECT_EQ(choice["paper"], "9 Push");
  EXPECT_EQ(cell(report.csv, "table_1", "pull", "corridor_ae", "action_choice")["paper"],
            "9 Pull, 1 No Correction");

  const std::string& md = report.markdown;
  EXPECT_NE(md.find("Sweep `s1` (paper, created 2026-01-02T03:04:05Z, 10 jobs): 10 runs read."),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| corridor_pc | 3 | 0, 1, 2 | 15 | 1, 2, 3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| corridor_ae | 1 | 3 | 5 | 4 |"), std::string::npos) << md;
  EXPECT_NE(
      md.find("Other experiments in the selection, not in the paper's tables: curves_demo (1)."),
      std::string::npos)
      << md;
  EXPECT_NE(md.find("| Expected correction | PC | PC paper | AE | AE paper | Mono | Mono paper |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| Push | 5 Push, 1 No Correction (3 runs) | 9 Push | 2 Push (1 run) | 8 "
                    "Push, 1 No Correction | 6 Push (3 runs) | 9 Push |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| No Correction | 100.0% [100.0, 100.0] | 100% | reproduced | 100.0% (1 "
                    "run) | 100% | no interval (1 run) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| All (25 trials in the paper) | 91.7% [55.8, 100.0] | 96% | reproduced |"),
            std::string::npos)
      << md;
}

// Runs smaller than the paper's (here 4-5 trials, one seed of corridor_ae) get a warning that
// their verdicts say little; runs of the paper's size do not.
TEST(PaperReport, WarnsWhenTheRunsAreTooSmallForTheVerdictsToMeanMuch) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_sweep(store);
  const std::string small = sweep_report(store).markdown;
  EXPECT_NE(small.find("**Small runs.** The selection has as few as 4 trials in a run (the "
                       "paper: 25) and 1 training seed of an experiment (the reproduction: 5)."),
            std::string::npos)
      << small;
  EXPECT_LT(small.find("**Small runs.**"), small.find("## Runs"));

  TempDir full_dir;
  ResultStore full(full_dir.file("r.sqlite"));
  testing::add_sweep(full, "s1", "paper", 3);
  std::vector<TrialSpec> trials;
  for (int t = 0; t < 25; ++t) trials.push_back({"push", "push", true});
  for (int job = 0; job < 3; ++job)
    testing::record_run(
        full, corridor_run("corridor_pc", job, {1.0, 1.0, 1.0, 0.8, 1.4, 3.0, 3.0}, trials));
  const std::string sized = sweep_report(full).markdown;
  EXPECT_EQ(sized.find("Small runs"), std::string::npos) << sized;

  // The paper's trials, but one seed run three times: only the seeds are named.
  TempDir one_seed_dir;
  ResultStore one_seed(one_seed_dir.file("r.sqlite"));
  testing::add_sweep(one_seed, "s1", "paper", 3);
  for (int job = 0; job < 3; ++job) {
    RunSpec spec = corridor_run("corridor_pc", job, {1.0, 1.0, 1.0, 0.8, 1.4, 3.0, 3.0}, trials);
    spec.config = "seed: 7\n";
    testing::record_run(one_seed, spec);
  }
  const std::string repeated = sweep_report(one_seed).markdown;
  EXPECT_NE(repeated.find("**Small runs.** The selection has 1 training seed of an experiment"),
            std::string::npos)
      << repeated;
}

TEST(PaperReport, TableTwoJudgesErrorsLowerIsBetter) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_sweep(store);
  const ReproductionReport report = sweep_report(store);
  // PC post-MP mean 3.0, 3.1, 3.2 cm: [2.85, 3.35], above the paper's 1.69.
  auto post = cell(report.csv, "table_2", "PC", "corridor_pc", "post_mp_error_mean_cm");
  EXPECT_NEAR(std::stod(post["mean"]), 3.1, 1e-12);
  EXPECT_NEAR(std::stod(post["ci_low"]), 2.8515862288249667, 1e-10);
  EXPECT_NEAR(std::stod(post["ci_high"]), 3.3484137711750335, 1e-10);
  EXPECT_EQ(post["paper"], "1.69");
  EXPECT_EQ(post["verdict"], "worse");
  // Mono cor-MP mean 1.00, 1.01, 1.02 cm: [0.985, 1.035], below the paper's 1.30.
  auto mono = cell(report.csv, "table_2", "Mono", "corridor_mono", "cor_mp_error_mean_cm");
  EXPECT_NEAR(std::stod(mono["ci_high"]), 1.0348413771175033, 1e-10);
  EXPECT_EQ(mono["verdict"], "better");
  EXPECT_EQ(cell(report.csv, "table_2", "AE", "corridor_ae", "cor_mp_error_max_cm")["verdict"],
            "no interval (1 run)");
  EXPECT_NE(report.markdown.find("| PC | 0.90 [0.65, 1.15] | 0.80 | reproduced | 1.45 [1.33, "
                                 "1.57] | 1.45 | reproduced | 3.10 [2.85, 3.35] | 1.69 | worse | "
                                 "3.10 [2.85, 3.35] | 3.19 | reproduced |"),
            std::string::npos)
      << report.markdown;
}

TEST(PaperReport, RopeSectionSaysThePaperHasNoNumber) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_sweep(store);
  const ReproductionReport report = sweep_report(store);
  auto none = cell(report.csv, "rope", "none", "rope_color", "task_success_rate_none");
  EXPECT_NEAR(std::stod(none["mean"]), 0.75, 1e-12);
  EXPECT_EQ(none["runs"], "2");
  EXPECT_EQ(none["verdict"], "no paper number");
  auto pooled = cell(report.csv, "rope", "lateral", "rope_color", "task_success_pooled");
  EXPECT_EQ(pooled["ours"], "1 of 4");
  EXPECT_NEAR(std::stod(pooled["mean"]), 0.25, 1e-12);
  EXPECT_EQ(cell(report.csv, "rope", "all", "rope_perfect", "task_success_rate")["ours"],
            "no runs");
  const std::string& md = report.markdown;
  EXPECT_NE(md.find("The paper gives no number to compare with"), std::string::npos) << md;
  // none before lateral (the rope task's order), then all.
  // Three floating-gripper columns and three on the arms without runs.
  EXPECT_NE(md.find("| none | 75.0% [0.0, 100.0] · pooled 3 of 4 | no runs | no runs | no runs | "
                    "no runs | no runs | no runs |\n"
                    "| lateral | 25.0% [0.0, 100.0] · pooled 1 of 4 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| all | 50.0% [0.0, 100.0] · pooled 4 of 8 | no runs | no runs | no runs | "
                    "no runs | no runs | no runs |"),
            std::string::npos)
      << md;
}

TEST(PaperReport, ListsTheFiguresItIsGiven) {
  EXPECT_EQ(figures_section({}), "## Figures\n\nNo figures listed.\n");
  const std::string figures =
      figures_section({{"plots/success.png", "Task success per seed"}, {"b.png", "B"}});
  EXPECT_NE(figures.find("![Figure 1: Task success per seed](plots/success.png)\n\n*Figure 1: "
                         "Task success per seed*"),
            std::string::npos)
      << figures;
  EXPECT_NE(figures.find("![Figure 2: B](b.png)"), std::string::npos) << figures;
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_sweep(store);
  const ReproductionReport report = sweep_report(store, {{"a.png", "A"}});
  EXPECT_NE(report.markdown.find("## Figures\n\n![Figure 1: A](a.png)"), std::string::npos);
}

TEST(PaperReport, WritesBothFilesAndRefusesRunsOfNoPaperExperiment) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_sweep(store);
  const ReproductionReport report = sweep_report(store);
  write_reproduction_report(report, dir.file("out/nested"));
  std::stringstream md, csv;
  md << std::ifstream(dir.file("out/nested/report.md")).rdbuf();
  csv << std::ifstream(dir.file("out/nested/report.csv")).rdbuf();
  EXPECT_EQ(md.str(), report.markdown);
  EXPECT_EQ(csv.str(), report.csv);
  EXPECT_EQ(csv.str().substr(0, csv.str().find('\n')),
            "table,row,group,quantity,runs,mean,ci_low,ci_high,ours,paper,verdict");

  ReportQuery others;
  others.experiments = {"curves_demo"};
  ReproductionInputs inputs;
  inputs.runs = load_run_summaries(store, others);
  EXPECT_THROW(reproduction_report(paper(), inputs), ReproductionError);
}

}  // namespace
}  // namespace corrmp
