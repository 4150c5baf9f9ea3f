// What a hostile or careless sweep definition gets from run_experiment (docs/sweeps.md): sweep
// ids that are not safe names refused wherever they are read, printed commands that run what
// they say, ranges at the edges of the integers, sweep-file list items taken as one value each,
// and fixed overrides that an axis would silently replace.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "config/test_files.hpp"
#include "store/result_store.hpp"
#include "support/store_sql.hpp"
#include "sweep/shell_words.hpp"
#include "sweep/sweep_command_support.hpp"

namespace corrmp {
namespace {

using testing::kTiny;
using testing::line_count;
using testing::Outcome;
using testing::read_text;
using testing::run;
using testing::TempDir;

// The jobs of a manifest printed by --print-config.
long jobs_in(const std::string& manifest) {
  long count = 0;
  for (size_t at = manifest.find("- index: "); at != std::string::npos;
       at = manifest.find("- index: ", at + 1)) {
    ++count;
  }
  return count;
}

TEST(SweepHostileInput, AConfigFileNameThatCannotNameASweepIsRefused) {
  TempDir dir;
  const std::string config = dir.write("x$(touch pwned);y.yaml", kTiny);
  const Outcome outcome = run(dir, shell_quoted(config) + " -m seed=0,1");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_NE(outcome.out.find("'x$(touch pwned);y' is not a valid sweep name"), std::string::npos)
      << outcome.out;
  EXPECT_EQ(line_count(outcome.out), 1) << outcome.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("runs")));
}

TEST(SweepHostileInput, ASweepIdThatIsNotASafeNameIsRefusedWhereverItIsRead) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  // From a manifest given to --sweep-job: its runs would go to <out>/tiny/../../escape.
  const std::string manifest =
      dir.write("manifest.yaml",
                "id: ../../escape\nname: tiny\nslurm: {cpus_per_task: 1, time: "
                "\"01:00:00\", memory: 4G, partition: \"\"}\njobs:\n  - index: 0\n    "
                "config: " +
                    config + "\n    overrides: []\n    axes: []\n");
  const Outcome job = run(dir, "--sweep-job " + manifest + " 0");
  EXPECT_EQ(job.exit_code, 2) << job.out;
  EXPECT_NE(job.out.find("manifest.yaml: id: '../../escape' is not a valid sweep id"),
            std::string::npos)
      << job.out;
  EXPECT_EQ(line_count(job.out), 1) << job.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("escape")));

  // From a database (a merged shard, say) whose manifest names another id than its row.
  ASSERT_EQ(run(dir, config + " -m seed=0,1").exit_code, 0);
  std::string id;
  {
    ResultStore store(dir.file("r.sqlite"));
    id = testing::query_text(store, "SELECT id FROM sweeps");
    testing::execute_sql(store, "UPDATE sweeps SET manifest = replace(manifest, 'id: " + id +
                                    "', 'id: ../../escape')");
    testing::execute_sql(store,
                         "UPDATE runs SET status = 'failed'");  // so that a resume runs them again
  }
  const Outcome resumed = run(dir, "--resume " + id);
  EXPECT_EQ(resumed.exit_code, 2) << resumed.out;
  EXPECT_NE(resumed.out.find("id: '../../escape' is not a valid sweep id"), std::string::npos)
      << resumed.out;
  EXPECT_EQ(line_count(resumed.out), 1) << resumed.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("escape")));

  // From the command line.
  const Outcome given = run(dir, "--resume '../x'");
  EXPECT_EQ(given.exit_code, 2) << given.out;
  EXPECT_EQ(given.out,
            "run_experiment: --resume: '../x' is not a valid sweep id (up to 128 "
            "letters, digits, '_', '-', '.', not starting with '.')\n");
}

// The commands --emit prints, pasted into bash, run with the very paths written (the test's
// bash has sbatch and run_experiment as functions that print their arguments).
TEST(SweepHostileInput, PrintedCommandsRunWithThePathsTheyName) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const std::string folder = dir.file("e $(touch pwned); `touch pwned2` x");
  const Outcome outcome = run(dir, config + " -m seed=0,1 --emit slurm " + shell_quoted(folder));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.out;
  std::string script = "cd " + shell_quoted(dir.path().string()) +
                       "\nsbatch() { printf '%s\\n' \"$@\"; }\nrun_experiment() { printf "
                       "'%s\\n' \"$@\"; }\n";
  for (const std::string prefix : {"submit with: ", "then merge: "}) {
    const size_t at = outcome.out.find(prefix);
    ASSERT_NE(at, std::string::npos) << outcome.out;
    const size_t begin = at + prefix.size();
    script += outcome.out.substr(begin, outcome.out.find('\n', begin) - begin) + "\n";
  }
  const std::string script_file = dir.write("paste.sh", script);
  const std::string printed = dir.file("printed.txt");
  ASSERT_EQ(std::system(("bash " + script_file + " > " + printed).c_str()), 0);
  EXPECT_EQ(read_text(printed), folder + "/sweep.sbatch\nmerge\n" + folder +
                                    "/shards/*.sqlite\n--db\n" + dir.file("r.sqlite") + "\n");
  EXPECT_FALSE(std::filesystem::exists(dir.file("pwned")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("pwned2")));
}

TEST(SweepHostileInput, RangesPastTheIntegerLimitsAreRefusedInOneLine) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  for (const std::string range : {"range(9223372036854775800,9223372036854775807,5)",
                                  "range(-9223372036854775800,-9223372036854775808,-5)"}) {
    const Outcome outcome = run(dir, config + " -m 'seed=" + range + "' --print-config");
    EXPECT_EQ(outcome.exit_code, 2) << range << ": " << outcome.out;
    EXPECT_NE(outcome.out.find("beyond the 64-bit integers"), std::string::npos) << outcome.out;
    EXPECT_EQ(line_count(outcome.out), 1) << outcome.out;
  }
  // Counts too large for the sweep are refused before any value is made.
  const Outcome huge = run(dir, config +
                                    " -m 'seed=range(-9223372036854775808,9223372036854775807)' "
                                    "--print-config");
  EXPECT_EQ(huge.exit_code, 2) << huge.out;
  EXPECT_NE(huge.out.find("more than 100000 values"), std::string::npos) << huge.out;
  const Outcome product = run(dir, config +
                                       " -m 'seed=range(1000)' 'evaluation.seed=range(1000)' "
                                       "--print-config");
  EXPECT_EQ(product.exit_code, 2) << product.out;
  EXPECT_NE(product.out.find("more than 100000 jobs"), std::string::npos) << product.out;
}

TEST(SweepHostileInput, ASweepFileListItemIsExactlyOneValue) {
  TempDir dir;
  dir.write("tiny.yaml", kTiny);
  const auto sweep_over = [&](const std::string& axis) {
    const std::string file = dir.write(
        "s.yaml", "sweep:\n  name: s\n  configs: [tiny.yaml]\n  axes:\n    " + axis + "\n");
    return run(dir, file + " --print-config");
  };
  const Outcome comma = sweep_over("experiment.description: [\"a,b\"]");
  ASSERT_EQ(comma.exit_code, 0) << comma.out;
  EXPECT_EQ(jobs_in(comma.out), 1) << comma.out;
  EXPECT_NE(comma.out.find(R"("experiment.description=\"a,b\"")"), std::string::npos) << comma.out;
  const Outcome quote = sweep_over("experiment.description: [\"it's\", b]");
  ASSERT_EQ(quote.exit_code, 0) << quote.out;
  EXPECT_EQ(jobs_in(quote.out), 2) << quote.out;
  EXPECT_NE(quote.out.find(R"("experiment.description=\"it's\"")"), std::string::npos) << quote.out;
  EXPECT_NE(quote.out.find(R"("experiment.description=b")"), std::string::npos) << quote.out;
  // A string that looks like a range is that string, which a seed cannot be.
  const Outcome range = sweep_over("seed: [\"range(0,3)\"]");
  EXPECT_EQ(range.exit_code, 2) << range.out;
  EXPECT_NE(range.out.find("s.yaml:5:11: sweep.axes.seed"), std::string::npos) << range.out;
  EXPECT_EQ(line_count(range.out), 1) << range.out;
}

TEST(SweepHostileInput, AnUnmatchedQuoteOnTheCommandLineIsAnError) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const Outcome outcome = run(dir, config + " -m \"experiment.description=it's,b\" --print-config");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_NE(outcome.out.find("unmatched ' in \"it's,b\""), std::string::npos) << outcome.out;
  EXPECT_EQ(line_count(outcome.out), 1) << outcome.out;
  // Quoted, the value is one.
  const Outcome quoted =
      run(dir, config + " -m 'experiment.description=\"it'\\''s\",b' --print-config");
  ASSERT_EQ(quoted.exit_code, 0) << quoted.out;
  EXPECT_EQ(jobs_in(quoted.out), 2) << quoted.out;
}

TEST(SweepHostileInput, AFixedOverrideOfASweptKeyIsRefusedNamingTheKey) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const Outcome command_line = run(dir, config + " -m seed=9 seed=3,4 --print-config");
  EXPECT_EQ(command_line.exit_code, 2) << command_line.out;
  EXPECT_NE(command_line.out.find("command-line override 'seed=9': seed: the sweep also varies "
                                  "seed (command-line sweep 'seed=3,4'), whose values would "
                                  "replace this one"),
            std::string::npos)
      << command_line.out;
  EXPECT_EQ(line_count(command_line.out), 1) << command_line.out;

  // A fixed override of the sweep file under one of its axes.
  const std::string file = dir.write("s.yaml",
                                     "sweep:\n  name: s\n  configs: [tiny.yaml]\n  overrides: "
                                     "[policy.network.width=4]\n  axes:\n    seed: [1, 2]\n    "
                                     "policy.network: [{width: 8}, {width: 16}]\n");
  const Outcome in_file = run(dir, file + " --print-config");
  EXPECT_EQ(in_file.exit_code, 2) << in_file.out;
  EXPECT_NE(in_file.out.find("s.yaml:4:15: sweep.overrides: policy.network.width: the sweep "
                             "also varies policy.network (" +
                             dir.file("s.yaml") + ":7:21)"),
            std::string::npos)
      << in_file.out;
  EXPECT_EQ(line_count(in_file.out), 1) << in_file.out;

  // The command line's fixed override against the file's axis.
  const std::string axes_only =
      dir.write("t.yaml", "sweep:\n  name: t\n  configs: [tiny.yaml]\n  axes:\n    seed: [1, 2]\n");
  const Outcome against_file = run(dir, axes_only + " seed=7 --print-config");
  EXPECT_EQ(against_file.exit_code, 2) << against_file.out;
  EXPECT_NE(against_file.out.find("command-line override 'seed=7': seed: the sweep also varies "
                                  "seed (" +
                                  dir.file("t.yaml") + ":5:11)"),
            std::string::npos)
      << against_file.out;
  EXPECT_EQ(line_count(against_file.out), 1) << against_file.out;

  // A fixed section that the axes refine keeps its other values: allowed.
  const Outcome refined =
      run(dir, config +
                   " -m 'policy.network={width: 4, encoder_layers: 2}' policy.network.width=8,16 "
                   "--print-config");
  EXPECT_EQ(refined.exit_code, 0) << refined.out;
  EXPECT_EQ(jobs_in(refined.out), 2) << refined.out;
}

}  // namespace
}  // namespace corrmp
