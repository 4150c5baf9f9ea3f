// End-to-end tests of run_experiment and report on damaged files: a result
// database of garbage bytes or truncated gives one line naming it and exit 2
// with nothing written; a 0-byte one is used as new with a notice by
// run_experiment and left as it was by report; a demonstration cache replaced
// by a directory is reported and the run goes through, every time; an output
// folder that cannot be made and missing or bad demonstration files are
// refused before a run is recorded.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "store/result_store.hpp"
#include "support/report_tool.hpp"
#include "support/store_sql.hpp"

namespace corrmp {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

using testing::ToolOutcome;
using Outcome = ToolOutcome;

std::string bytes_of(const std::string& path) { return testing::read(path); }

Outcome run_experiment(const TempDir& dir, const std::string& args) {
  return testing::run_experiment_tool(dir, args);
}

Outcome report(const TempDir& dir) { return testing::report_tool(dir, ""); }

int lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

const std::string kTiny =
    "experiment: {name: tiny}\nseed: 3\ndemonstrations: {type: curve_family, train: 4, "
    "validation: 2, time_steps: 10}\npolicy:\n  type: segmented_cnmp\n  network: {width: 8}\n"
    "  training: {updates: 50, validate_every: 50}\n";

// Runs the tiny experiment and the report tool on the test's r.sqlite (left
// damaged in `dir`), expecting one refusing line from each and no writes.
void expect_refused(const TempDir& dir, const std::string& problem) {
  const std::string db = dir.file("r.sqlite");
  const std::string before = bytes_of(db);
  const Outcome run = run_experiment(dir, dir.write("tiny.yaml", kTiny));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "run_experiment: " + db + ": not a usable result database (" + problem +
                         "); move it aside or choose another database file\n");
  EXPECT_FALSE(fs::exists(dir.file("runs"))) << "no run directory for a run never recorded";
  const Outcome tool = report(dir);
  EXPECT_EQ(tool.exit_code, 2);
  EXPECT_EQ(lines(tool.err), 1) << tool.err;
  EXPECT_NE(tool.err.find(db + ": not a usable result database"), std::string::npos) << tool.err;
  EXPECT_EQ(bytes_of(db), before) << "the damaged database is left as it was";
  EXPECT_FALSE(fs::exists(db + "-journal"));
}

TEST(DamagedFilesTools, AGarbageDatabaseIsRefusedInOneLine) {
  TempDir dir;
  std::string garbage;
  for (int i = 0; i < 1000; ++i) garbage += "these are not the bytes of a database\n";
  dir.write("r.sqlite", garbage);
  expect_refused(dir, "not an SQLite database");
}

TEST(DamagedFilesTools, ATruncatedDatabaseIsRefusedInOneLine) {
  TempDir dir;
  ASSERT_EQ(run_experiment(dir, dir.write("tiny.yaml", kTiny)).exit_code, 0);
  ASSERT_GT(fs::file_size(dir.file("r.sqlite")), 3 * 4096u);
  fs::resize_file(dir.file("r.sqlite"), 2 * 4096);
  fs::remove_all(dir.file("runs"));
  expect_refused(dir, "the file is damaged or truncated");
}

TEST(DamagedFilesTools, AZeroByteDatabaseIsUsedAsNewWithANotice) {
  TempDir dir;
  const std::string db = dir.write("r.sqlite", "");
  const Outcome run = run_experiment(dir, dir.write("tiny.yaml", kTiny) + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find(db + ": empty file (0 bytes); using it as a new result database"),
            std::string::npos)
      << run.err;
  ResultStore store(db);
  EXPECT_EQ(testing::query_int(store, "SELECT COUNT(*) FROM runs WHERE status = 'completed'"), 1);
}

// The cache path taken by a directory: each run reports it and collects the
// demonstrations again, with the results of the first run.
TEST(DamagedFilesTools, ADirectoryInPlaceOfTheDemonstrationCacheIsNeverFatal) {
  TempDir dir;
  const std::string args = std::string(PROJECT_DIR) +
                           "/configs/corridor_pc.yaml demonstrations.train=4 "
                           "demonstrations.validation=2 policy.training.updates=100 "
                           "policy.training.validate_every=50 policy.network.width=8 "
                           "evaluation.trials=1";
  ASSERT_EQ(run_experiment(dir, args).exit_code, 0);
  std::string cache;
  for (const auto& entry : fs::directory_iterator(dir.file("runs/cache"))) {
    if (entry.path().extension() == ".bin") cache = entry.path().string();
  }
  ASSERT_FALSE(cache.empty());
  fs::remove(cache);
  fs::create_directories(cache);
  for (int run = 2; run <= 3; ++run) {
    const Outcome outcome = run_experiment(dir, args);
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_NE(outcome.err.find("demonstration cache '" + cache +
                               "': is a directory; collecting the demonstrations again"),
              std::string::npos)
        << outcome.err;
  }
  ResultStore store(dir.file("r.sqlite"));
  for (int run_id : {2, 3}) {
    EXPECT_EQ(
        testing::query_int(store,
                           "SELECT COUNT(*) FROM (SELECT name, value FROM metrics WHERE "
                           "run_id = 1 EXCEPT SELECT name, value FROM metrics WHERE run_id = " +
                               std::to_string(run_id) + ")"),
        0);
  }
}

}  // namespace
}  // namespace corrmp

namespace corrmp {
namespace {

// Refused before a run is recorded: exit 2, one line, no run in the database.
void expect_no_run(const TempDir& dir, const Outcome& outcome, const std::string& message) {
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_EQ(lines(outcome.err), 1) << outcome.err;
  EXPECT_NE(outcome.err.find(message), std::string::npos) << outcome.err;
  if (fs::exists(dir.file("r.sqlite"))) {
    ResultStore store(dir.file("r.sqlite"));
    EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs"), 0);
  }
}

TEST(DamagedFilesTools, AnOutputFolderThatCannotBeMadeIsRefusedBeforeARunIsRecorded) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const std::string file = dir.write("afile", "in the way\n");
  const Outcome outcome =
      testing::run_tool(dir, std::string(RUN_EXPERIMENT_BIN) + " " + config + " --db " +
                                 dir.file("r.sqlite") + " --out " + file);
  expect_no_run(dir, outcome, "--out: cannot make the output folder " + file + "/tiny");
  EXPECT_EQ(bytes_of(file), "in the way\n");
}

TEST(DamagedFilesTools, MissingDemonstrationFilesAreRefusedBeforeARunIsRecorded) {
  TempDir dir;
  const std::string config =
      dir.write("files.yaml",
                "experiment: {name: files}\nseed: 3\ndemonstrations: {type: trajectory_files, "
                "paths: [" +
                    dir.file("no-such-recordings") +
                    "], output_columns: [x]}\npolicy:\n  type: segmented_cnmp\n  network: "
                    "{width: 8}\n  training: {updates: 50, validate_every: 50}\n");
  const Outcome outcome = run_experiment(dir, config);
  expect_no_run(dir, outcome,
                "demonstrations.paths: '" + dir.file("no-such-recordings") + "' does not exist");
  EXPECT_FALSE(fs::exists(dir.file("runs")));
}

std::string trajectory_files_config(const std::string& path, const std::string& output,
                                    const std::string& context) {
  return "experiment: {name: files}\nseed: 3\ndemonstrations: {type: trajectory_files, paths: [" +
         path + "], time_column: t, output_columns: [" + output + "], context_columns: [" +
         context +
         "]}\npolicy:\n  type: segmented_cnmp\n  network: {width: 8}\n  training: {updates: 50, "
         "validate_every: 50}\n";
}

// The files' contents are read when the config is loaded, by the readers train_cnmp uses: a bad
// file refuses the run as a missing one does, naming the file (and line) and what is wrong.
TEST(DamagedFilesTools, DemonstrationFilesWithBadContentsAreRefusedBeforeARunIsRecorded) {
  TempDir dir;
  const std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3 }\n";
  std::string npy("\x93NUMPY\x01\x00", 8);
  npy += static_cast<char>(header.size());
  npy += '\0';
  npy += header;
  struct Case {
    std::string file, contents, output, key, problem;
  };
  const std::vector<Case> cases = {
      {"nan.csv", "t,x,c\n0,0,1\n1,nan,1\n", "x", "demonstrations.paths",
       ":3: non-finite value \"nan\" in column 'x'"},
      {"ragged.csv", "t,x,c\n0,0,1\n1,0.5,1,7\n", "x", "demonstrations.paths",
       ":3: ragged row: expected 3 fields (as in the header), got 4"},
      {"columns.csv", "t,x,c\n0,0,1\n1,0.5,1\n", "y", "demonstrations",
       ": no column 'y' (columns: t, x, c)"},
      {"header.npy", npy, "c1", "demonstrations.paths",
       ": malformed .npy header (expected ',' or ')' in tuple"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string file = dir.write(c.file, c.contents);
    const Outcome outcome =
        run_experiment(dir, dir.write("files.yaml", trajectory_files_config(file, c.output, "c")));
    expect_no_run(dir, outcome, c.key + ": " + file + c.problem);
    EXPECT_EQ(outcome.err.rfind(dir.file("files.yaml:3:"), 0), 0u) << outcome.err;
    EXPECT_FALSE(fs::exists(dir.file("runs")));
  }
  for (int i = 0; i < 5; ++i) {
    dir.write("good/" + std::to_string(i) + ".csv",
              "t,x,c\n0,0,1\n1,0.5,1\n2," + std::to_string(i) + ",1\n");
  }
  const Outcome good = run_experiment(
      dir,
      dir.write("files.yaml", trajectory_files_config(dir.file("good"), "x", "c")) + " --quiet");
  ASSERT_EQ(good.exit_code, 0) << good.err;
  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs"), 1);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'completed'"), 1);
}

// report only reads: a 0-byte database (what `touch` leaves) is named as empty, with the exit
// codes of a database without runs, and left as it was, with no -wal or -shm file; a path
// without a file is refused and not created.
TEST(DamagedFilesTools, ReportLeavesAZeroByteDatabaseAsItWas) {
  TempDir dir;
  const std::string db = dir.write("r.sqlite", "");
  const Outcome table = report(dir);
  EXPECT_EQ(table.exit_code, 1);
  EXPECT_EQ(table.err, "report: " + db + ": no runs recorded (empty database)\n");
  EXPECT_EQ(table.out, "");
  const Outcome compare = testing::report_tool(dir, "--compare");
  EXPECT_EQ(compare.exit_code, 2);
  EXPECT_EQ(compare.err, table.err);
  const Outcome sweep = testing::report_tool(dir, "--sweep some-sweep");
  EXPECT_EQ(sweep.exit_code, 2);
  EXPECT_EQ(sweep.err, table.err);
  ASSERT_TRUE(fs::is_regular_file(db));
  EXPECT_EQ(fs::file_size(db), 0u) << "the empty database is left as it was";
  for (const char* suffix : {"-wal", "-shm", "-journal"}) {
    EXPECT_FALSE(fs::exists(db + suffix)) << suffix;
  }

  fs::remove(db);
  const Outcome missing = report(dir);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err, "report: no result database at '" + db + "' (see --db)\n");
  EXPECT_FALSE(fs::exists(db));

  { ResultStore no_runs(db); }  // a database with its schema and no runs: the same exit codes
  EXPECT_EQ(report(dir).exit_code, table.exit_code);
  EXPECT_EQ(testing::report_tool(dir, "--compare").exit_code, compare.exit_code);
  EXPECT_EQ(testing::report_tool(dir, "--sweep some-sweep").exit_code, sweep.exit_code);
}

}  // namespace
}  // namespace corrmp
