// Tests of the report tool's --compare and --reproduction: the files it
// writes, what it prints, and one-line usage errors with exit code 2
// (docs/architecture.md, "Command line").
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/test_files.hpp"
#include "support/recorded_runs.hpp"
#include "support/report_tool.hpp"
#include "support/store_sql.hpp"

namespace corrmp {
namespace {

using testing::read;
using testing::report_tool;
using testing::RunSpec;
using testing::TempDir;
using testing::ToolOutcome;

// Sweep "s1": two corridor_pc runs (4 and 3 of 4) and two corridor_mono runs
// (1 and 2 of 4); one corridor_pc run outside it.
void record_runs(const TempDir& dir) {
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
    spec.metrics = {{"task_success_rate", successes / 4.0}, {"cor_mp_error_mean_cm", 1.0}};
    testing::record_run(store, spec);
  }
  RunSpec outside;
  outside.experiment = "corridor_pc";
  outside.trials = testing::trials_of("push", 4, 0);
  outside.metrics = {{"task_success_rate", 0.0}};
  testing::record_run(store, outside);
}

TEST(ReportTool, ComparesTheRunsOfASweep) {
  TempDir dir;
  record_runs(dir);
  const ToolOutcome csv = report_tool(dir, "--compare --sweep s1 --csv --baseline corridor_mono");
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  // 7 of 8 against 3 of 8: fisher.test gives 0.1189 (= 17 / 143).
  EXPECT_NE(csv.out.find("\ndifference,corridor_pc,corridor_mono,task_success_rate,2,8,7,0.5,"),
            std::string::npos)
      << csv.out;
  EXPECT_NE(csv.out.find(",8,3,0.11888111888111"), std::string::npos) << csv.out;
  // The run outside the sweep is left out: 2 runs, 8 trials.
  EXPECT_NE(csv.out.find("\npooled_success,corridor_pc,,task_success,2,8,7,0.875,"),
            std::string::npos)
      << csv.out;

  const ToolOutcome files = report_tool(dir, "--compare --sweep s1 --out " + dir.file("cmp"));
  ASSERT_EQ(files.exit_code, 0) << files.err;
  EXPECT_NE(read(dir.file("cmp/compare.md")).find("| corridor_pc | 2 | 8 | 7 of 8"),
            std::string::npos);
  const std::string written = read(dir.file("cmp/compare.csv"));
  EXPECT_EQ(written.rfind("kind,group,versus,metric", 0), 0u);
  // corridor_pc's success 0.875 -/+ 1.588 across its two seeds, clipped.
  EXPECT_NE(written.find("\nmean,corridor_pc,,task_success_rate,2,8,,0.875,0,1,,,\n"),
            std::string::npos)
      << written;

  const ToolOutcome by_seed = report_tool(dir, "--compare --sweep s1 --by seed");
  ASSERT_EQ(by_seed.exit_code, 0) << by_seed.err;
  EXPECT_NE(by_seed.out.find("| seed=3 | 1 | 4 | 2 of 4"), std::string::npos) << by_seed.out;
}

// Grouped by a setting both experiments share, each group pools the two
// experiments: said on stderr and in compare.md, the numbers unchanged.
TEST(ReportTool, WarnsWhenAGroupPoolsExperiments) {
  TempDir dir;
  {
    ResultStore store(dir.file("r.sqlite"));
    testing::add_sweep(store, "s2", "policies", 4);
    int job = 0;
    for (const std::string experiment : {"corridor_pc", "corridor_ae"}) {
      for (int seed : {0, 1}) {
        RunSpec spec;
        spec.experiment = experiment;
        spec.config = "seed: " + std::to_string(seed) + "\npolicy: {type: segmented}\n";
        spec.sweep_id = "s2";
        spec.job_index = job++;
        spec.axes = "{\"seed\":\"" + std::to_string(seed) + "\"}";
        spec.trials = testing::trials_of("push", 4, 2 + seed);
        spec.metrics = {{"task_success_rate", (2 + seed) / 4.0}};
        testing::record_run(store, spec);
      }
    }
  }
  const std::string warning =
      "report: warning: group policy.type=segmented pools experiments corridor_pc, corridor_ae "
      "(averaged as if seeds)\n";
  const ToolOutcome md = report_tool(dir, "--compare --sweep s2 --by policy.type");
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_EQ(md.err, warning);
  EXPECT_NE(md.out.find("\n- group policy.type=segmented pools experiments corridor_pc, "
                        "corridor_ae\n"),
            std::string::npos)
      << md.out;
  EXPECT_NE(md.out.find("| policy.type=segmented | 4 | 16 | 10 of 16"), std::string::npos)
      << md.out;
  const ToolOutcome files =
      report_tool(dir, "--compare --sweep s2 --by policy.type --out " + dir.file("cmp"));
  ASSERT_EQ(files.exit_code, 0) << files.err;
  EXPECT_EQ(files.err, warning);
  EXPECT_NE(read(dir.file("cmp/compare.md")).find("pools experiments corridor_pc, corridor_ae"),
            std::string::npos);
  const ToolOutcome by_experiment = report_tool(dir, "--compare --sweep s2");
  ASSERT_EQ(by_experiment.exit_code, 0) << by_experiment.err;
  EXPECT_EQ(by_experiment.err, "");  // seeds only
}

TEST(ReportTool, WritesTheReproductionReport) {
  TempDir dir;
  record_runs(dir);
  const ToolOutcome ok = report_tool(dir, "--reproduction --sweep s1 --out " + dir.file("repro"));
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const std::string md = read(dir.file("repro/report.md"));
  EXPECT_NE(md.find("Sweep `s1` (paper"), std::string::npos) << md;
  EXPECT_NE(md.find("| corridor_pc | 2 | 0, 1 | 8 |"), std::string::npos) << md;
  EXPECT_NE(read(dir.file("repro/report.csv"))
                .find("\ntable_1,all,corridor_pc,task_success_rate,2,0.875,"),
            std::string::npos);
}

TEST(ReportTool, SaysWhatIsWrongWithACompareInOneLine) {
  TempDir dir;
  record_runs(dir);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--compare --sweep nope",
       "report: unknown sweep id 'nope' in '" + dir.file("r.sqlite") + "'\n"},
      {"--compare --experiment corridor_ae corridor_pc",
       "report: experiment 'corridor_ae' has no selected run\n"},
      {"--compare --run 99", "report: run 99 is not among the selected runs\n"},
      {"--compare --baseline corridor_ae",
       "report: no group 'corridor_ae' to compare with (the groups: 'corridor_pc', "
       "'corridor_mono')\n"},
      {"--compare --sweep s1 --by nosuch.key",
       "report: --by 'nosuch.key': no selected run has this setting\n"},
      {"--compare --sweep s1 --by sed",
       "report: --by 'sed': no selected run has this setting (did you mean 'seed'?)\n"},
      {"--by seed", "report: --by and --baseline need --compare\n"},
      {"--compare --reproduction", "report: --compare and --reproduction exclude each other\n"},
      {"--reproduction --sweep s1", "report: --reproduction needs --out DIR\n"},
      {"--out x", "report: --out needs --compare or --reproduction\n"},
      {"--reproduction --run 42 --out " + dir.file("x"),
       "report: run 42 is not among the selected runs\n"},
  };
  for (const auto& [args, message] : cases) {
    const ToolOutcome bad = report_tool(dir, args);
    EXPECT_EQ(bad.exit_code, 2) << args;
    EXPECT_EQ(bad.err, message) << args;
  }
  // A database written before sweeps were recorded.
  {
    ResultStore store(dir.file("r.sqlite"));
    testing::execute_sql(
        store,
        "DROP INDEX IF EXISTS runs_sweep; ALTER TABLE runs DROP COLUMN axes; ALTER TABLE runs "
        "DROP COLUMN job_index; ALTER TABLE runs DROP COLUMN sweep_id; DROP TABLE sweeps;");
  }
  const ToolOutcome old = report_tool(dir, "--compare --sweep s1");
  EXPECT_EQ(old.exit_code, 2);
  EXPECT_EQ(old.err, "report: '" + dir.file("r.sqlite") + "' records no sweeps (see --sweep)\n");
  const ToolOutcome still = report_tool(dir, "--compare --csv");
  EXPECT_EQ(still.exit_code, 0) << still.err;
  EXPECT_NE(still.out.find("\npooled_success,corridor_pc,,task_success,3,12,7,"), std::string::npos)
      << still.out;
}

// An --out that is a file, or lies below one, is named in one line (exit 2), for each of the
// options that write there; the file is left as it was.
TEST(ReportTool, AnOutFolderThatIsAFileIsRefusedNamingIt) {
  TempDir dir;
  record_runs(dir);
  const std::string file = dir.write("afile", "in the way\n");
  for (const std::string& out : {file, file + "/below"}) {
    for (const std::string& args :
         {"--compare --sweep s1 --out " + out, "--reproduction --sweep s1 --out " + out,
          "--plot-success experiment --sweep s1 --out " + out}) {
      const ToolOutcome bad = report_tool(dir, args);
      EXPECT_EQ(bad.exit_code, 2) << args << "\n" << bad.err;
      EXPECT_EQ(bad.err, "report: --out " + out + ": '" + file + "' is a file, not a folder\n")
          << args;
    }
  }
  EXPECT_EQ(read(file), "in the way\n");
}

// A selection whose runs all failed or were interrupted: the message counts them and names the
// option that shows them, instead of suggesting there are none.
TEST(ReportTool, NoCompletedRunSaysHowManyFailedAndWhichOptionShowsThem) {
  TempDir dir;
  {
    ResultStore store(dir.file("r.sqlite"));
    RunRecord run;
    run.experiment = "curves_demo";
    run.config = "seed: 0\n";
    run.config_hash = "h";
    store.end_run(store.begin_run(run), RunStatus::failed, "std::bad_alloc");
    store.end_run(store.begin_run(run), RunStatus::failed, "std::bad_alloc");
    store.end_run(store.begin_run(run), RunStatus::interrupted, "Ctrl-C");
  }
  const std::string db = dir.file("r.sqlite");
  const ToolOutcome table = report_tool(dir, "");
  EXPECT_EQ(table.exit_code, 1);
  EXPECT_EQ(table.err, "report: no completed run in '" + db +
                           "' matches, but 2 failed and 1 interrupted do: --all shows them\n");
  const ToolOutcome compared = report_tool(dir, "--compare");
  EXPECT_EQ(compared.exit_code, 2);
  EXPECT_EQ(compared.err, table.err);
  const ToolOutcome all = report_tool(dir, "--all");
  EXPECT_EQ(all.exit_code, 0) << all.err;
  EXPECT_NE(all.out.find("| failed |"), std::string::npos) << all.out;
}

}  // namespace
}  // namespace corrmp
