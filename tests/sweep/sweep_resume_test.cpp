// Resuming a sweep (docs/sweeps.md, "Resuming"): one driver per sweep and database whatever
// path names the database, a base config edited since the sweep started refused, and a job
// that finds its earlier attempt still 'running', its process ended, marks it interrupted in its
// run.json too.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "config/test_files.hpp"
#include "store/result_store.hpp"
#include "support/child_process.hpp"
#include "support/store_sql.hpp"
#include "sweep/sweep_command_support.hpp"

namespace corrmp {
namespace {

using testing::kTiny;
using testing::line_count;
using testing::Outcome;
using testing::read_text;
using testing::run;
using testing::slow_tiny;
using testing::TempDir;

// Stops a child the test started, whatever the test's outcome.
class Child {
 public:
  explicit Child(pid_t pid) : pid_(pid) {}
  ~Child() {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_;
};

TEST(SweepResume, ASecondDriverThroughASymlinkToTheDatabaseIsRefused) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", slow_tiny());
  const std::string db = dir.file("r.sqlite");
  const Child driver(testing::spawn_quietly(
      {RUN_EXPERIMENT_BIN, config, "-m", "seed=0,1", "--db", db, "--out", dir.file("runs")}));
  ASSERT_GT(testing::wait_until_positive(db, "SELECT count(*) FROM runs WHERE status = 'running'"),
            0);
  std::string id;
  {
    ResultStore store(db);
    id = testing::query_text(store, "SELECT id FROM sweeps");
  }
  std::filesystem::create_symlink(db, dir.file("link.sqlite"));
  std::filesystem::create_directory_symlink(dir.path(), dir.file("alias"));
  for (const std::string& other : {dir.file("link.sqlite"), dir.file("alias/r.sqlite")}) {
    // Bounded: a driver that did not see the lock would run the jobs again.
    const Outcome second = run(dir, "--resume " + id + " --threads 1", other, 30);
    EXPECT_EQ(second.exit_code, 1) << other << ": " << second.out;
    EXPECT_NE(second.out.find("another process is running this sweep"), std::string::npos)
        << second.out;
  }
  ResultStore store(db);
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs"), 1);
}

TEST(SweepResume, ABaseConfigEditedSinceTheSweepStartedIsRefused) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  ASSERT_EQ(run(dir, config + " -m seed=0,1").exit_code, 0);
  std::string id;
  {
    ResultStore store(dir.file("r.sqlite"));
    id = testing::query_text(store, "SELECT id FROM sweeps");
  }
  // A comment changes no value: the sweep resumes.
  dir.write("tiny.yaml", kTiny + "# the same values\n");
  const Outcome same = run(dir, "--resume " + id);
  EXPECT_EQ(same.exit_code, 0) << same.out;

  std::string edited = kTiny;
  edited.replace(edited.find("width: 8"), 8, "width: 9");
  dir.write("tiny.yaml", edited);
  const Outcome resumed = run(dir, "--resume " + id);
  EXPECT_EQ(resumed.exit_code, 2) << resumed.out;
  EXPECT_NE(
      resumed.out.find(config + ": changed since sweep " + id + " started (its hash differs)"),
      std::string::npos)
      << resumed.out;
  EXPECT_EQ(line_count(resumed.out), 1) << resumed.out;
  // A job's own process refuses it too (a Slurm task submitted again, say).
  const Outcome job =
      run(dir, "--sweep-job " + dir.file("runs/sweeps/" + id + "/manifest.yaml") + " 0");
  EXPECT_EQ(job.exit_code, 2) << job.out;
  EXPECT_NE(job.out.find(config + ": changed since sweep " + id), std::string::npos) << job.out;
}

// A resumed job finds its earlier attempt still 'running' (its process, killed with the
// driver, ended but not yet reaped) and marks it interrupted: its run.json says so as well.
TEST(SweepResume, AnEarlierAttemptMarkedInterruptedByItsJobSaysSoInItsRunJson) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", slow_tiny());
  ASSERT_EQ(run(dir, config + " -m seed=0,1 --emit slurm " + dir.file("emit")).exit_code, 0);
  const std::string db = dir.file("r.sqlite");
  const std::vector<std::string> job = {RUN_EXPERIMENT_BIN,
                                        "--sweep-job",
                                        dir.file("emit/manifest.yaml"),
                                        "0",
                                        "--db",
                                        db,
                                        "--out",
                                        dir.file("runs"),
                                        "--threads",
                                        "1"};
  const Child first(testing::spawn_quietly(job));
  ASSERT_GT(testing::wait_until_positive(
                db, "SELECT count(*) FROM runs WHERE status = 'running' AND out_dir != ''"),
            0);
  std::string run_json;
  {
    ResultStore store(db);
    run_json = testing::query_text(store, "SELECT out_dir FROM runs WHERE id = 1") + "/run.json";
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (read_text(run_json).find("\"status\": \"running\"") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_NE(read_text(run_json).find("\"status\": \"running\""), std::string::npos);
  ASSERT_EQ(::kill(first.pid(), SIGKILL), 0);
  siginfo_t ended{};
  ASSERT_EQ(::waitid(P_PID, static_cast<id_t>(first.pid()), &ended, WEXITED | WNOWAIT), 0);

  const Child second(testing::spawn_quietly(job));
  ASSERT_GT(testing::wait_until_positive(
                db, "SELECT count(*) FROM runs WHERE id = 1 AND status = 'interrupted'"),
            0);
  // The database is updated first, the run.json right after it.
  const auto json_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (read_text(run_json).find("\"status\": \"interrupted\"") == std::string::npos &&
         std::chrono::steady_clock::now() < json_deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const std::string text = read_text(run_json);
  EXPECT_NE(text.find("\"status\": \"interrupted\""), std::string::npos) << text;
  EXPECT_NE(text.find("an earlier attempt at this sweep job ended without finishing"),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace corrmp
