// Tests of the SQLite result store: schema version, concurrent writers in two
// processes, interrupted-run detection, atomic completion.
#include "store/result_store.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "config/test_files.hpp"

namespace corrmp {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using ::testing::ThrowsMessage;

RunRecord a_run() {
  RunRecord run;
  run.experiment = "test";
  run.config = "seed: 1\n";
  run.config_hash = "abc";
  run.seed = 1;
  return run;
}

TEST(ResultStore, CreatesTheSchemaInWalModeWithItsVersion) {
  TempDir dir;
  ResultStore store(dir.file("sub/r.sqlite"));
  EXPECT_EQ(store.query_int("PRAGMA user_version"), ResultStore::kSchemaVersion);
  EXPECT_EQ(store.query_text("PRAGMA journal_mode"), "wal");
  const int64_t id = store.begin_run(a_run());
  EXPECT_EQ(store.query_text("SELECT status FROM runs WHERE id = " + std::to_string(id)),
            "running");
}

TEST(ResultStore, RefusesANewerSchemaVersion) {
  TempDir dir;
  const std::string path = dir.file("r.sqlite");
  {
    ResultStore store(path);
    store.execute("PRAGMA user_version = 99");
  }
  EXPECT_THAT([&] { ResultStore again(path); },
              ThrowsMessage<StoreError>(HasSubstr("schema version 99 is newer")));
}

TEST(ResultStore, CompleteRunWritesTrialsMetricsAndStatusTogether) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  const int64_t id = store.begin_run(a_run());
  store.complete_run(id,
                     {{0, "{\"x\":1}", "push", "push", true, "", ""},
                      {1, "{\"x\":2}", "pull", "none", false, "touched the corridor", ""}},
                     {{"task_success_rate", 0.5}});
  const std::string where = " WHERE run_id = " + std::to_string(id);
  EXPECT_EQ(store.query_int("SELECT COUNT(*) FROM trials" + where), 2);
  EXPECT_EQ(store.query_text("SELECT failure FROM trials" + where + " AND trial = 1"),
            "touched the corridor");
  EXPECT_EQ(store.query_text("SELECT value FROM metrics" + where), "0.5");
  EXPECT_EQ(store.query_text("SELECT status FROM runs WHERE id = " + std::to_string(id)),
            "completed");
}

TEST(ResultStore, AFailedTransactionWritesNothing) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  const int64_t id = store.begin_run(a_run());
  EXPECT_THROW(store.transaction([&] {
    store.add_metrics(id, {{"a", 1.0}});  // nested BEGIN fails: transaction rolls back
  }),
               StoreError);
  EXPECT_THROW(store.transaction([&] {
    store.execute("INSERT INTO metrics (run_id, name, value) VALUES (1, 'b', 2)");
    throw std::runtime_error("stage failed");
  }),
               std::runtime_error);
  EXPECT_EQ(store.query_int("SELECT COUNT(*) FROM metrics"), 0);
}

TEST(ResultStore, TwoProcessesWritingOneThousandRowsEachLoseNone) {
  TempDir dir;
  const std::string path = dir.file("shared.sqlite");
  int64_t run_id = 0;
  {
    ResultStore store(path);
    run_id = store.begin_run(a_run());
  }
  auto write_rows = [&](const std::string& prefix) {
    ResultStore store(path);
    for (int i = 0; i < 1000; ++i) {
      store.add_metrics(run_id, {{prefix + std::to_string(i), static_cast<double>(i)}});
    }
  };
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    try {
      write_rows("child_");
    } catch (...) {
      _exit(1);
    }
    _exit(0);
  }
  write_rows("parent_");
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  ResultStore store(path);
  EXPECT_EQ(store.query_int("SELECT COUNT(*) FROM metrics WHERE name LIKE 'child_%'"), 1000);
  EXPECT_EQ(store.query_int("SELECT COUNT(*) FROM metrics WHERE name LIKE 'parent_%'"), 1000);
  EXPECT_EQ(store.query_int("SELECT COUNT(DISTINCT name) FROM metrics"), 2000);
}

TEST(ResultStore, ARunLeftRunningByAKilledProcessIsMarkedInterrupted) {
  TempDir dir;
  const std::string path = dir.file("r.sqlite");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ResultStore store(path);
    store.begin_run(a_run());
    _exit(0);  // dies without finishing the run
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ResultStore store(path);
  const int64_t live = store.begin_run(a_run());  // this process is alive: left alone
  EXPECT_EQ(store.mark_interrupted_runs().size(), 1u);
  EXPECT_EQ(store.query_int("SELECT COUNT(*) FROM runs WHERE status = 'interrupted'"), 1);
  EXPECT_EQ(store.query_text("SELECT status FROM runs WHERE id = " + std::to_string(live)),
            "running");
  EXPECT_TRUE(store.mark_interrupted_runs().empty());
}

// A sweep job's run left 'running' is an earlier attempt, on whatever host, unless its process is
// alive on this host (the same job started twice at once): that one is left alone. A process
// that ended but is not reaped yet (a zombie) has ended.
TEST(ResultStore, AJobsRunsAreMarkedInterruptedUnlessTheirProcessIsAliveHere) {
  TempDir dir;
  const std::string path = dir.file("r.sqlite");
  RunRecord job = a_run();
  job.sweep_id = "s-1";
  job.job_index = 0;
  pid_t children[2] = {};
  for (pid_t& child : children) {
    child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ResultStore store(path);
      store.begin_run(job);
      _exit(0);  // dies without finishing the run
    }
    siginfo_t ended{};
    ASSERT_EQ(waitid(P_PID, static_cast<id_t>(child), &ended, WEXITED | WNOWAIT), 0);
  }
  ASSERT_EQ(waitpid(children[0], nullptr, 0), children[0]);  // children[1] stays a zombie
  ResultStore store(path);
  const int64_t live = store.begin_run(job);
  const int64_t elsewhere = store.begin_run(job);
  store.execute("UPDATE runs SET host = 'another-host' WHERE id = " + std::to_string(elsewhere));
  EXPECT_EQ(store.mark_job_runs_interrupted("s-1", 0).size(), 3u);
  ASSERT_EQ(waitpid(children[1], nullptr, 0), children[1]);
  EXPECT_EQ(store.query_text("SELECT status FROM runs WHERE id = " + std::to_string(live)),
            "running");
  EXPECT_EQ(store.query_text("SELECT status FROM runs WHERE id = " + std::to_string(elsewhere)),
            "interrupted");
}

}  // namespace
}  // namespace corrmp
