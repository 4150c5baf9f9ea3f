// Tests of run reports: flattened configs, the settings a sweep varies, the
// selection of runs, and the Markdown and CSV tables.
#include "report/run_report.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <fstream>
#include <sstream>

#include "config/test_files.hpp"
#include "support/recorded_runs.hpp"
#include "support/report_tool.hpp"

namespace corrmp {
namespace {

using testing::record_scored_run;
using testing::TempDir;

// The error columns are whatever the runs recorded, in the order they did:
// another task's segments and unit get theirs, and a run without one shows "-".
TEST(RunReport, ErrorColumnsFollowWhatTheRunsRecorded) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_scored_run(store, "corridor_pc", "seed: 0\n", 1.0, 0.2);
  const int64_t id = store.begin_run({"rope", "seed: 0\n", "hash", 0, "", false, "", "", 0, ""});
  store.complete_run(id, {},
                     testing::as_migrated({{"task_success_rate", 0.5},
                                           {"pre_mp_error_mean_mm", 3.0},
                                           {"pre_mp_error_max_mm", 4.0},
                                           {"cor_mp_error_mean_cm", 0.5},
                                           {"cor_mp_error_max_cm", 0.7}}));
  const auto runs = load_run_summaries(store, {});
  const std::string markdown = report_markdown(runs, {});
  EXPECT_NE(markdown.find("| decision match | cor-MP error mean / max (cm) | pre-MP error mean / "
                          "max (mm) |"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| 0.20 / 0.40 | - |"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| 0.50 / 0.70 | 3.00 / 4.00 |"), std::string::npos) << markdown;
  const std::string csv = report_csv(runs, {});
  EXPECT_NE(csv.find("cor_mp_error_mean_cm,cor_mp_error_max_cm,pre_mp_error_mean_mm,"
                     "pre_mp_error_max_mm\n"),
            std::string::npos)
      << csv;
}

// A run with no environment (curves_demo, trajectory files) records the held-out
// demonstrations' errors, which get their own columns.
TEST(RunReport, HeldOutErrorsOfRunsWithoutAnEnvironmentGetColumns) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  const int64_t id =
      store.begin_run({"curves_demo", "seed: 0\n", "hash", 0, "", false, "", "", 0, ""});
  store.complete_run(
      id, {}, testing::as_migrated({{"full_error_mean", 0.00412}, {"full_error_max", 0.0183}}));
  const auto runs = load_run_summaries(store, {});
  const std::string markdown = report_markdown(runs, {});
  EXPECT_NE(markdown.find("| full error mean / max (held-out) |"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| 0.00412 / 0.0183 |"), std::string::npos) << markdown;
  EXPECT_NE(report_csv(runs, {}).find("full_error_mean,full_error_max\n"), std::string::npos);
}

TEST(RunReport, FlattensConfigsToDottedKeys) {
  const auto flat = flatten_yaml(
      "seed: 3\nevaluation: {seed: 2, trials: 25}\nshape: [1, 2]\n"
      "segments:\n  - {segment: cor, state: [corridor_x]}\n");
  EXPECT_EQ(flat.at("seed"), "3");
  EXPECT_EQ(flat.at("evaluation.seed"), "2");
  EXPECT_EQ(flat.at("evaluation.trials"), "25");
  EXPECT_EQ(flat.at("shape"), "[1, 2]");
  EXPECT_EQ(flat.at("segments.0.segment"), "cor");
  EXPECT_EQ(flat.at("segments.0.state"), "[corridor_x]");
  EXPECT_EQ(flat.size(), 6u);
}

TEST(RunReport, TabulatesRunsWithTheSettingsTheyVary) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_scored_run(store, "sweep", "seed: 0\nevaluation: {seed: 1, trials: 4}\n", 1.0, 0.2);
  record_scored_run(store, "sweep", "seed: 0\nevaluation: {seed: 2, trials: 4}\n", 0.5, 0.4);
  record_scored_run(store, "other", "seed: 0\nnote: a\n", 0.25, 0.1);
  record_scored_run(store, "other", "seed: 0\nnote: a|b\n", 0.25, 0.1);
  const int64_t failed =
      store.begin_run({"sweep", "seed: 9\n", "hash", 0, "", false, "", "", 0, ""});
  store.end_run(failed, RunStatus::failed, "for the test");

  const auto runs = load_run_summaries(store, {});
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs[0].trials, 4);
  EXPECT_EQ(runs[1].metrics.at("task_success_rate"), 0.5);
  const auto varying = varying_settings(runs);
  EXPECT_EQ(varying.at("sweep"), std::vector<std::string>{"evaluation.seed"});
  EXPECT_EQ(varying.at("other"), std::vector<std::string>{"note"});

  ReportFormat format;
  format.extra_metrics = {"demonstrations_train", "missing"};
  const std::string markdown = report_markdown(runs, format);
  EXPECT_NE(
      markdown.find("| 1 | sweep | evaluation.seed=1 | 4 of 4 | 75% | 0.20 / 0.40 | 100 | - |"),
      std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| 2 | sweep | evaluation.seed=2 | 2 of 4 | 75% | 0.40 / 0.80 | 100 |"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| 3 | other | note=a | 1 of 4 |"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| 4 | other | note=a\\|b | 1 of 4 |"), std::string::npos) << markdown;

  const std::string csv = report_csv(runs, {});
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "run,experiment,status,varies,trials,task_success_rate,decision_match_rate,"
            "cor_mp_error_mean_cm,cor_mp_error_max_cm");
  EXPECT_NE(csv.find("\n2,sweep,completed,evaluation.seed=2,4,0.5,0.75,0.4,0.8\n"),
            std::string::npos)
      << csv;

  ReportQuery query;
  query.experiments = {"sweep"};
  query.completed_only = false;
  const auto with_failed = load_run_summaries(store, query);
  ASSERT_EQ(with_failed.size(), 3u);
  EXPECT_EQ(with_failed[2].status, RunStatus::failed);
  // With --all the Markdown shows each run's status; by default it has none.
  EXPECT_EQ(markdown.find("status"), std::string::npos) << markdown;
  ReportFormat with_status;
  with_status.status_column = true;
  const std::string all = report_markdown(with_failed, with_status);
  EXPECT_NE(all.find("| run | experiment | status | varies | task success | decision match |"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("\n|---|---|---|---|---|---|---|\n"), std::string::npos) << all;
  EXPECT_NE(all.find("\n| 1 | sweep | completed | "), std::string::npos) << all;
  EXPECT_NE(all.find("\n| " + std::to_string(failed) + " | sweep | failed | "), std::string::npos)
      << all;
  query.last = 1;
  const auto newest = load_run_summaries(store, query);
  ASSERT_EQ(newest.size(), 1u);
  EXPECT_EQ(newest[0].id, failed);
  ReportQuery by_id;
  by_id.runs = {3, 1};  // any order given; oldest first returned
  const auto picked = load_run_summaries(store, by_id);
  ASSERT_EQ(picked.size(), 2u);
  EXPECT_EQ(picked[0].id, 1);
  EXPECT_EQ(picked[1].id, 3);
}

// Reference rows go below the runs; an error only they have gets its column.
TEST(RunReport, AppendsReferenceRowsWithTheirErrorColumns) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_scored_run(store, "lift_a", "seed: 0\n", 1.0, 0.2);
  ReportFormat format;
  format.reference_rows = {
      {"paper: a",
       "3 of 4",
       "75%",
       {{"cor_mp_error_mean_cm", "0.10 / 0.20"}, {"arc_mp_error_mean_cm", "1.50 / 4.00"}}}};
  const std::string markdown = report_markdown(load_run_summaries(store, {}), format);
  EXPECT_NE(markdown.find("| | paper: a | | 3 of 4 | 75% | 0.10 / 0.20 | 1.50 / 4.00 |"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| 1 | lift_a |  | 4 of 4 | 75% | 0.20 / 0.40 | - |"), std::string::npos)
      << markdown;
}

using testing::ToolOutcome;

ToolOutcome run_report_tool(const TempDir& dir, const std::string& args) {
  const std::string out = dir.file("out.txt"), err = dir.file("err.txt");
  const int status =
      std::system((std::string(REPORT_BIN) + " " + args + " >" + out + " 2>" + err).c_str());
  auto read = [](const std::string& path) {
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    return text.str();
  };
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(out), read(err)};
}

TEST(ReportTool, PrintsTheRunsOrSaysWhatIsWrongInOneLine) {
  TempDir dir;
  {
    ResultStore store(dir.file("r.sqlite"));
    record_scored_run(store, "corridor_mono", "seed: 0\n", 0.5, 0.3);
  }
  const ToolOutcome ok = run_report_tool(dir, "--db " + dir.file("r.sqlite") + " --csv");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("\n1,corridor_mono,completed,,4,0.5,0.75,0.3,0.6\n"), std::string::npos)
      << ok.out;

  // --all: an interrupted run beside the completed one, its status shown in
  // Markdown as in CSV; without --all the table has no status column.
  {
    ResultStore store(dir.file("r.sqlite"));
    const int64_t id =
        store.begin_run({"corridor_mono", "seed: 1\n", "hash", 0, "", false, "", "", 0, ""});
    store.end_run(id, RunStatus::interrupted, "killed");
  }
  const ToolOutcome all = run_report_tool(dir, "--db " + dir.file("r.sqlite") + " --all");
  EXPECT_EQ(all.exit_code, 0) << all.err;
  EXPECT_NE(all.out.find("\n| 1 | corridor_mono | completed | seed=0 | 2 of 4 |"),
            std::string::npos)
      << all.out;
  EXPECT_NE(all.out.find("\n| 2 | corridor_mono | interrupted | seed=1 | - |"), std::string::npos)
      << all.out;
  const ToolOutcome completed = run_report_tool(dir, "--db " + dir.file("r.sqlite"));
  EXPECT_EQ(completed.exit_code, 0) << completed.err;
  EXPECT_EQ(completed.out.find("status"), std::string::npos) << completed.out;
  EXPECT_NE(completed.out.find("\n| 1 | corridor_mono |  | 2 of 4 |"), std::string::npos)
      << completed.out;

  const ToolOutcome missing = run_report_tool(dir, "--db " + dir.file("none.sqlite"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err,
            "report: no result database at '" + dir.file("none.sqlite") + "' (see --db)\n");
  EXPECT_FALSE(std::filesystem::exists(dir.file("none.sqlite")));

  const ToolOutcome unmatched =
      run_report_tool(dir, "--db " + dir.file("r.sqlite") + " --experiment nothing");
  EXPECT_EQ(unmatched.exit_code, 1);
  EXPECT_NE(unmatched.err.find("no run"), std::string::npos) << unmatched.err;

  const ToolOutcome bad = run_report_tool(dir, "--db " + dir.file("r.sqlite") + " --last 0");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  // A metric no run recorded (a typo) is refused, not a column of '-'; --paper is Markdown.
  const ToolOutcome typo =
      run_report_tool(dir, "--db " + dir.file("r.sqlite") + " --metric task_succes_rate");
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_EQ(typo.err,
            "report: --metric 'task_succes_rate': no selected run recorded it (did you mean "
            "'task_success_rate'?)\n");
  const ToolOutcome known =
      run_report_tool(dir, "--db " + dir.file("r.sqlite") + " --metric task_success_rate");
  EXPECT_EQ(known.exit_code, 0) << known.err;
  const ToolOutcome csv_paper =
      run_report_tool(dir, "--db " + dir.file("r.sqlite") + " --csv --paper");
  EXPECT_EQ(csv_paper.exit_code, 2);
  EXPECT_NE(csv_paper.err.find("--paper's rows are Markdown only"), std::string::npos)
      << csv_paper.err;
}

}  // namespace
}  // namespace corrmp
