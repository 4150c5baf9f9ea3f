// run_experiment's sweeps end to end (docs/sweeps.md): bad axes refused before
// anything is written, every job recorded with its sweep and axes, a sweep
// stopped by Ctrl-C or a closed terminal (SIGHUP) with its runs recorded, a sweep
// killed with kill -9 resumed to exactly one completed run per job, and a
// Slurm round trip through a real single-node Slurm (skipped where Slurm
// cannot start).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "config/test_files.hpp"
#include "store/result_store.hpp"
#include "support/child_process.hpp"
#include "support/local_slurm.hpp"
#include "support/store_sql.hpp"
#include "sweep/shell_words.hpp"
#include "sweep/sweep_command_support.hpp"

namespace corrmp {
namespace {

using testing::files_named;
using testing::kTiny;
using testing::Outcome;
using testing::read_text;
using testing::run;
using testing::TempDir;

TEST(SweepCommand, BadAxesExitTwoWithOneLineAndWriteNothing) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"policy.training.updatez=1,2", "policy.training.updatez: unknown key"},
      {"seed=choice()", "choice() needs at least one value"},
      {"seed=range(4,2)", "range(4, 2, 1) is empty"},
      {"seed=range(0,x)", "'x' is not an integer"},
      {"seed=1,,2", "empty value"},
      {"policy.training.updates=100,-5", "sweep job 1: policy.training.updates=-5"},
  };
  for (const auto& [axis, expected] : cases) {
    const Outcome outcome = run(dir, config + " -m '" + axis + "'");
    EXPECT_EQ(outcome.exit_code, 2) << axis;
    EXPECT_NE(outcome.out.find(expected), std::string::npos) << axis << ": " << outcome.out;
    EXPECT_EQ(std::count(outcome.out.begin(), outcome.out.end(), '\n'), 1) << outcome.out;
    EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite"))) << axis;
    EXPECT_FALSE(std::filesystem::exists(dir.file("runs"))) << axis;
  }
}

// A sweep file's axis or override with a bad key or value is reported at its place in the
// file, not as a command-line override.
TEST(SweepCommand, BadValuesOfASweepFileNameTheirPlaceInTheFile) {
  TempDir dir;
  dir.write("tiny.yaml", kTiny);
  const std::string head = "sweep:\n  name: bad\n  configs: [tiny.yaml]\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"  axes:\n    policy.training.updatez: [100, 200]\n",
       "bad.yaml:5:30: sweep.axes.policy.training.updatez: unknown key (did you mean 'updates'?)"},
      {"  overrides: [seed=1, policy.network.widht=4]\n",
       "bad.yaml:4:23: sweep.overrides: policy.network.widht: unknown key (did you mean 'width'?)"},
      {"  zip:\n    seed: [1, 2]\n    policy.training.updates: [100, -5]\n",
       "bad.yaml:6:30: sweep.zip.policy.training.updates: value -5 is out of range"},
      // A misspelt part of the key, and a key inside the value: both named.
      {"  axes:\n    policy.trainingg.updates: [100, 200]\n",
       "bad.yaml:5:31: sweep.axes.policy.trainingg.updates: policy.trainingg: unknown key"},
      {"  overrides: ['policy.network={widht: 4}']\n",
       "bad.yaml:4:15: sweep.overrides: policy.network.widht: unknown key"},
  };
  for (const auto& [section, expected] : cases) {
    const std::string file = dir.write("bad.yaml", head + section);
    const Outcome outcome = run(dir, file);
    EXPECT_EQ(outcome.exit_code, 2) << section;
    EXPECT_NE(outcome.out.find(expected), std::string::npos) << outcome.out;
    EXPECT_EQ(outcome.out.find("command-line override"), std::string::npos) << outcome.out;
    EXPECT_EQ(std::count(outcome.out.begin(), outcome.out.end(), '\n'), 1) << outcome.out;
    EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite"))) << section;
  }
  // A bad value given on the command line for a key the file also sets is the command line's.
  const std::string fixed =
      dir.write("fixed.yaml", head + "  overrides: [policy.training.updates=100]\n");
  const Outcome override_given = run(dir, fixed + " policy.training.updates=-5");
  EXPECT_EQ(override_given.exit_code, 2);
  EXPECT_NE(override_given.out.find("command-line override 'policy.training.updates=-5'"),
            std::string::npos)
      << override_given.out;
  // The same key on the command line is the command line's.
  const Outcome command_line = run(dir, dir.file("tiny.yaml") + " -m policy.training.updatez=1,2");
  EXPECT_NE(command_line.out.find("command-line override 'policy.training.updatez=1'"),
            std::string::npos)
      << command_line.out;
}

TEST(SweepCommand, AnAxisWithoutMinusMSaysToAddIt) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const Outcome outcome = run(dir, config + " seed=1,2");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.out.find("got '1,2' (to sweep over 'seed=1,2', add -m)\n"), std::string::npos)
      << outcome.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
  // Other bad overrides get no such hint.
  const Outcome plain = run(dir, config + " seed=x");
  EXPECT_EQ(plain.exit_code, 2);
  EXPECT_EQ(plain.out.find("-m"), std::string::npos) << plain.out;
}

TEST(SweepCommand, RecordsEveryJobWithItsSweepAndAxes) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const Outcome outcome = run(dir, config + " -m 'seed=range(0,2)' policy.network.width=4,8 -j 2");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.out;
  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'completed'"), 4);
  EXPECT_EQ(testing::query_int(store, "SELECT count(DISTINCT sweep_id) FROM runs"), 1);
  EXPECT_EQ(testing::query_int(store, "SELECT jobs FROM sweeps"), 4);
  EXPECT_EQ(testing::query_text(store, "SELECT axes FROM runs WHERE job_index = 3"),
            R"({"seed":"1","policy.network.width":"8"})");
  EXPECT_EQ(testing::query_int(store, "SELECT seed FROM runs WHERE job_index = 3"), 1);
  // Resuming a finished sweep runs nothing more.
  const std::string id = testing::query_text(store, "SELECT id FROM sweeps");
  const Outcome again = run(dir, "--resume " + id);
  EXPECT_EQ(again.exit_code, 0) << again.out;
  EXPECT_NE(again.out.find("0 completed, 0 failed, 0 interrupted (4 completed before)"),
            std::string::npos)
      << again.out;
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs"), 4);
  EXPECT_EQ(run(dir, "--resume no-such-sweep").exit_code, 2);
  EXPECT_EQ(run(dir, config + " --resume " + id).exit_code, 2);
}

TEST(SweepCommand, ResumeAndMergeRefuseMissingDatabasesWritingNothing) {
  TempDir dir;
  const Outcome resumed = run(dir, "--resume some-sweep");
  EXPECT_EQ(resumed.exit_code, 2);
  EXPECT_NE(resumed.out.find("no database at"), std::string::npos) << resumed.out;
  const std::string merge = std::string(RUN_EXPERIMENT_BIN) + " merge " +
                            dir.file("missing.sqlite") + " --db " + dir.file("r.sqlite") +
                            " 2> /dev/null";
  EXPECT_EQ(WEXITSTATUS(std::system(merge.c_str())), 2);
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
}

TEST(SweepCommand, AnUnusableDatabaseIsRefusedBeforeAnythingIsWritten) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  dir.write("r.sqlite", "garbage\n");
  const Outcome outcome = run(dir, config + " -m seed=0,1");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_NE(outcome.out.find("r.sqlite"), std::string::npos) << outcome.out;
  EXPECT_EQ(std::count(outcome.out.begin(), outcome.out.end(), '\n'), 1) << outcome.out;
  EXPECT_EQ(read_text(dir.file("r.sqlite")), "garbage\n");
  EXPECT_FALSE(std::filesystem::exists(dir.file("runs")));  // no manifest, no sweep folder
  EXPECT_EQ(files_named(dir.path(), ".lock"), 0);
}

TEST(SweepCommand, MakesTheDatabaseFolderAndRemovesItsLockWhenDone) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const std::string db = dir.file("new/folder/r.sqlite");
  const Outcome outcome = run(dir, config + " -m seed=0,1", db);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.out;
  ResultStore store(db);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'completed'"), 2);
  EXPECT_EQ(files_named(dir.file("new/folder"), ".lock"), 0);
}

TEST(SweepCommand, CtrlCStopsTheJobsAndCountsTheOnesNeverStarted) {
  TempDir dir;
  std::string slow = kTiny;
  slow.replace(slow.find("updates: 200"), 12, "updates: 10000000");  // minutes: Ctrl-C comes first
  const std::string config = dir.write("tiny.yaml", slow);
  const std::string log = dir.file("driver.txt");
  const pid_t driver = ::fork();
  if (driver == 0) {
    const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(out, STDERR_FILENO);
    const std::string db = dir.file("r.sqlite"), runs = dir.file("runs");
    ::execl(RUN_EXPERIMENT_BIN, RUN_EXPERIMENT_BIN, config.c_str(), "-m", "seed=range(0,5)", "-j",
            "2", "--db", db.c_str(), "--out", runs.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Both first jobs under way, then Ctrl-C.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int64_t running = 0;
  while (running < 2 && std::chrono::steady_clock::now() < deadline) {
    running = testing::wait_until_positive(dir.file("r.sqlite"),
                                           "SELECT count(*) FROM runs WHERE status = 'running'");
    if (running < 2) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_EQ(running, 2);
  ::kill(driver, SIGINT);
  int status = 0;
  const auto stop_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (::waitpid(driver, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > stop_deadline) {
      ::kill(driver, SIGKILL);
      ::waitpid(driver, &status, 0);
      FAIL() << "the sweep did not stop within 60 s of Ctrl-C";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const std::string out = read_text(log);
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 130) << out;
  EXPECT_NE(out.find("0 completed, 0 failed, 2 interrupted, 3 not started"), std::string::npos)
      << out;
  EXPECT_NE(out.find("resume with: run_experiment --resume "), std::string::npos) << out;
  EXPECT_NE(out.find(" -j 2\n"), std::string::npos) << out;
  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs"), 2);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'interrupted'"), 2);
}

// A closed terminal (SIGHUP to the driver and its jobs, one process group) stops the sweep as
// Ctrl-C does: the runs recorded interrupted, the lock removed, exit 130, and a resume command
// that, pasted into bash, runs with the very paths given.
// nohup starts a process with SIGHUP ignored; the run must keep it ignored and finish.
TEST(SweepCommand, UnderNohupAHangupIsIgnoredAndTheRunFinishes) {
  TempDir dir;
  std::string seconds_long = testing::kTiny;  // long enough to be running when the signal comes
  seconds_long.replace(seconds_long.find("updates: 200"), 12, "updates: 40000");
  const std::string config = dir.write("tiny.yaml", seconds_long);
  const std::string db = dir.file("r.sqlite"), runs = dir.file("runs");
  const pid_t child = ::fork();
  if (child == 0) {
    ::setpgid(0, 0);
    ::signal(SIGHUP, SIG_IGN);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execl(RUN_EXPERIMENT_BIN, RUN_EXPERIMENT_BIN, config.c_str(), "--db", db.c_str(), "--out",
            runs.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(child, child);
  ASSERT_GT(testing::wait_until_positive(db, "SELECT count(*) FROM runs WHERE status = 'running'"),
            0);
  ::kill(-child, SIGHUP);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
  ResultStore store(db);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'completed'"), 1);
}

TEST(SweepCommand, AHangupStopsTheSweepLikeCtrlC) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", testing::slow_tiny());
  const std::string db = dir.file("db $(touch pwned)/r.sqlite"), runs = dir.file("runs");
  const std::string log = dir.file("driver.txt");
  const pid_t driver = ::fork();
  if (driver == 0) {
    ::setpgid(0, 0);
    const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(out, STDERR_FILENO);
    ::execl(RUN_EXPERIMENT_BIN, RUN_EXPERIMENT_BIN, config.c_str(), "-m", "seed=range(0,3)", "-j",
            "2", "--db", db.c_str(), "--out", runs.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(driver, driver);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int64_t running = 0;
  while (running < 2 && std::chrono::steady_clock::now() < deadline) {
    running =
        testing::wait_until_positive(db, "SELECT count(*) FROM runs WHERE status = 'running'");
    if (running < 2) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_EQ(running, 2);
  ::kill(-driver, SIGHUP);
  int status = 0;
  const auto stop_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (::waitpid(driver, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > stop_deadline) {
      ::kill(-driver, SIGKILL);
      ::waitpid(driver, &status, 0);
      FAIL() << "the sweep did not stop within 60 s of SIGHUP";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const std::string out = read_text(log);
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), 130) << out;
  EXPECT_NE(out.find("0 completed, 0 failed, 2 interrupted, 1 not started"), std::string::npos)
      << out;
  EXPECT_EQ(files_named(dir.file("db $(touch pwned)"), ".lock"), 0);
  std::string id;
  {
    ResultStore store(db);
    EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'interrupted'"),
              2);
    EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'running'"), 0);
    id = testing::query_text(store, "SELECT id FROM sweeps");
  }
  const std::string prefix = "resume with: ";
  const size_t at = out.find(prefix);
  ASSERT_NE(at, std::string::npos) << out;
  const std::string command =
      out.substr(at + prefix.size(), out.find('\n', at) - at - prefix.size());
  const std::string script =
      dir.write("paste.sh", "cd " + shell_quoted(dir.path().string()) +
                                "\nrun_experiment() { printf '%s\\n' \"$@\"; }\n" + command + "\n");
  const std::string printed = dir.file("printed.txt");
  ASSERT_EQ(std::system(("bash " + script + " > " + printed).c_str()), 0);
  EXPECT_EQ(read_text(printed),
            "--resume\n" + id + "\n--db\n" + db + "\n--out\n" + runs + "\n-j\n2\n");
  EXPECT_FALSE(std::filesystem::exists(dir.file("pwned")));
}

// merge checks every shard before it merges any or makes the target.
TEST(SweepCommand, MergeRefusesABadShardBeforeMergingAny) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const std::string first = dir.file("job-0.sqlite"), second = dir.file("job-1.sqlite");
  ASSERT_EQ(run(dir, config + " seed=1", first).exit_code, 0);
  ASSERT_EQ(run(dir, config + " seed=2", second).exit_code, 0);
  const std::string bad = dir.write("x.yaml", "a: b\n");
  const std::string target = dir.file("merged.sqlite");
  const auto merge = [&](const std::string& shards) {
    const std::string log = dir.file("merge.txt");
    const std::string command = std::string(RUN_EXPERIMENT_BIN) + " merge " + shards + " --db " +
                                target + " >" + log + " 2>&1";
    const int status = std::system(command.c_str());
    return Outcome{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(log)};
  };
  const Outcome refused = merge(first + " " + bad + " " + second);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.out, "run_experiment merge: " + bad +
                             ": not a result database to merge (file is not a database)\n");
  EXPECT_FALSE(std::filesystem::exists(target));
  const Outcome merged = merge(first + " " + second);
  ASSERT_EQ(merged.exit_code, 0) << merged.out;
  ResultStore store(target);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'completed'"), 2);
}

TEST(SweepCommand, AKilledSweepResumesToExactlyOneCompletedRunPerJob) {
  TempDir dir;
  std::string slow = kTiny;
  slow.replace(slow.find("updates: 200"), 12, "updates: 4000");
  const std::string config = dir.write("tiny.yaml", slow);
  const pid_t driver =
      testing::spawn_quietly({RUN_EXPERIMENT_BIN, config, "-m", "seed=range(0,6)", "-j", "2",
                              "--db", dir.file("r.sqlite"), "--out", dir.file("runs")});
  // Kill the driver once a job has completed and others are under way.
  const int64_t completed = testing::wait_until_positive(
      dir.file("r.sqlite"), "SELECT count(*) FROM runs WHERE status = 'completed'");
  ASSERT_GT(completed, 0);
  ::kill(driver, SIGKILL);
  ::waitpid(driver, nullptr, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // its jobs die with it

  std::string id;
  {
    ResultStore store(dir.file("r.sqlite"));
    id = testing::query_text(store, "SELECT id FROM sweeps");
    EXPECT_LT(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'completed'"), 6);
  }
  const Outcome resumed = run(dir, "--resume " + id + " -j 2");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.out;
  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'completed'"), 6);
  EXPECT_EQ(testing::query_int(store,
                               "SELECT count(DISTINCT job_index) FROM runs WHERE status = "
                               "'completed'"),
            6);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'running'"), 0);
}

// Two jobs needing the same demonstrations at the same time: one collects them,
// the other waits for its lock and reuses them; both evaluate the same trials.
TEST(SweepCommand, ConcurrentJobsShareOneCacheEntry) {
  TempDir dir;
  const Outcome outcome =
      run(dir, std::string(PROJECT_DIR) +
                   "/configs/corridor_pc.yaml demonstrations.train=6 demonstrations.validation=3 "
                   "policy.training.updates=100 policy.training.validate_every=50 "
                   "evaluation.trials=2 -m policy.network.width=8,9 -j 2");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.out;
  ResultStore store(dir.file("r.sqlite"));
  int collected = 0, reused = 0;
  for (int job = 0; job < 2; ++job) {
    const std::string run_log =
        read_text(testing::query_text(
                      store, "SELECT out_dir FROM runs WHERE job_index = " + std::to_string(job)) +
                  "/log.txt");
    if (run_log.find("reusing cached demonstrations") != std::string::npos) {
      ++reused;
    } else if (run_log.find("demonstrations: 9 in") != std::string::npos) {
      ++collected;
    }
  }
  EXPECT_EQ(collected, 1);
  EXPECT_EQ(reused, 1);
  int caches = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.file("runs/cache"))) {
    caches += entry.path().extension() == ".bin";
    EXPECT_EQ(entry.path().extension() == ".tmp", false) << entry.path();
  }
  EXPECT_EQ(caches, 1);
  EXPECT_EQ(testing::query_text(store,
                                "SELECT group_concat(scenario, '|') FROM trials WHERE run_id = "
                                "(SELECT id FROM runs WHERE job_index = 0)"),
            testing::query_text(store,
                                "SELECT group_concat(scenario, '|') FROM trials WHERE run_id = "
                                "(SELECT id FROM runs WHERE job_index = 1)"));
}

TEST(SweepCommand, RunsOnARealSlurmAndMergesTheShardsOnce) {
  TempDir dir;
  testing::LocalSlurm slurm(dir.file("slurm"));
  if (!slurm.running()) {
    if (slurm.unavailable()) GTEST_SKIP() << slurm.reason();
    FAIL() << slurm.reason();
  }
  const std::string config = dir.write("tiny.yaml", kTiny);
  const Outcome outcome = run(dir, config + " -m seed=0,1 --launcher slurm --wait --threads 1");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.out;
  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'completed'"), 2);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM sweeps"), 1);
  // Both shards number their run 1: the run directories still differ.
  EXPECT_EQ(testing::query_int(store, "SELECT count(DISTINCT out_dir) FROM runs"), 2);
  const std::string id = testing::query_text(store, "SELECT id FROM sweeps");
  const std::string shards = dir.file("runs/sweeps/" + id + "/shards");
  EXPECT_TRUE(std::filesystem::exists(shards + "/job-0.sqlite"));
  EXPECT_TRUE(std::filesystem::exists(shards + "/job-1.sqlite"));
  // Merging again changes nothing.
  const std::string merge = std::string(RUN_EXPERIMENT_BIN) + " merge " + shards +
                            "/job-0.sqlite " + shards + "/job-1.sqlite --db " +
                            dir.file("r.sqlite") + " > /dev/null";
  EXPECT_EQ(std::system(merge.c_str()), 0);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs"), 2);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM trials"),
            testing::query_int(
                store, "SELECT count(*) FROM trials WHERE run_id IN (SELECT id FROM runs)"));
}

TEST(SweepCommand, RefusesSlurmResourcesAnSbatchLineCannotHoldWritingNothing) {
  TempDir dir;
  dir.write("tiny.yaml", kTiny);
  const std::string sweep =
      dir.write("sweep.yaml", "sweep: {name: s, configs: [tiny.yaml], slurm: {time: '1 hour'}}\n");
  const std::string expected =
      "sweep.yaml:1:54: sweep.slurm.time: '1 hour' is not a Slurm value (letters, digits and "
      ":-_.,+ only)\n";
  const Outcome outcome = run(dir, sweep + " --emit slurm " + dir.file("emit"));
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_NE(outcome.out.find(expected), std::string::npos) << outcome.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("emit")));
  // The same sweep run here is refused too: the file is wrong wherever it runs.
  const Outcome local = run(dir, sweep);
  EXPECT_EQ(local.exit_code, 2) << local.out;
  EXPECT_NE(local.out.find(expected), std::string::npos) << local.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
}

TEST(SweepCommand, EmitsTheSlurmFilesWithoutSubmitting) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const Outcome outcome = run(dir, config + " -m seed=0,1,2 --emit slurm " + dir.file("emit"));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.out;
  std::ifstream script(dir.file("emit/sweep.sbatch"));
  std::stringstream text;
  text << script.rdbuf();
  EXPECT_NE(text.str().find("#SBATCH --array=0-2"), std::string::npos) << text.str();
  EXPECT_TRUE(std::filesystem::exists(dir.file("emit/manifest.yaml")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
}

}  // namespace
}  // namespace corrmp
