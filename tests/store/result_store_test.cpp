// Tests of the SQLite result store: schema version, concurrent writers in two
// processes, interrupted-run detection, atomic completion.
#include "store/result_store.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "config/test_files.hpp"
#include "store/run_queries.hpp"
#include "support/store_sql.hpp"

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
  EXPECT_EQ(testing::query_int(store, "PRAGMA user_version"), ResultStore::kSchemaVersion);
  EXPECT_EQ(testing::query_text(store, "PRAGMA journal_mode"), "wal");
  const int64_t id = store.begin_run(a_run());
  EXPECT_EQ(testing::query_text(store, "SELECT status FROM runs WHERE id = " + std::to_string(id)),
            "running");
}

TEST(ResultStore, RefusesANewerSchemaVersion) {
  TempDir dir;
  const std::string path = dir.file("r.sqlite");
  {
    ResultStore store(path);
    testing::execute_sql(store, "PRAGMA user_version = 99");
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
  EXPECT_EQ(testing::query_int(store, "SELECT COUNT(*) FROM trials" + where), 2);
  EXPECT_EQ(testing::query_text(store, "SELECT failure FROM trials" + where + " AND trial = 1"),
            "touched the corridor");
  EXPECT_EQ(testing::query_text(store, "SELECT value FROM metrics" + where), "0.5");
  EXPECT_EQ(testing::query_text(store, "SELECT status FROM runs WHERE id = " + std::to_string(id)),
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
    testing::execute_sql(store, "INSERT INTO metrics (run_id, name, value) VALUES (1, 'b', 2)");
    throw std::runtime_error("stage failed");
  }),
               std::runtime_error);
  EXPECT_EQ(testing::query_int(store, "SELECT COUNT(*) FROM metrics"), 0);
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
  EXPECT_EQ(testing::query_int(store, "SELECT COUNT(*) FROM metrics WHERE name LIKE 'child_%'"),
            1000);
  EXPECT_EQ(testing::query_int(store, "SELECT COUNT(*) FROM metrics WHERE name LIKE 'parent_%'"),
            1000);
  EXPECT_EQ(testing::query_int(store, "SELECT COUNT(DISTINCT name) FROM metrics"), 2000);
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
  EXPECT_EQ(testing::query_int(store, "SELECT COUNT(*) FROM runs WHERE status = 'interrupted'"), 1);
  EXPECT_EQ(
      testing::query_text(store, "SELECT status FROM runs WHERE id = " + std::to_string(live)),
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
  testing::execute_sql(
      store, "UPDATE runs SET host = 'another-host' WHERE id = " + std::to_string(elsewhere));
  EXPECT_EQ(store.mark_job_runs_interrupted("s-1", 0).size(), 3u);
  ASSERT_EQ(waitpid(children[1], nullptr, 0), children[1]);
  EXPECT_EQ(
      testing::query_text(store, "SELECT status FROM runs WHERE id = " + std::to_string(live)),
      "running");
  EXPECT_EQ(
      testing::query_text(store, "SELECT status FROM runs WHERE id = " + std::to_string(elsewhere)),
      "interrupted");
}

// What a metric means is stored with it and read back as declared: a unit, a range with either
// end open, a direction, and the report heading its statistics share.
TEST(ResultStore, AMetricsDeclarationIsStoredAndReadBack) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  const int64_t id = store.begin_run(a_run());
  const std::vector<MetricRecord> metrics = {
      {"task_success_rate", 0.75, rate_metric(Better::higher)},
      {"reach_mp_error_mean_mm", 3.5, error_statistic("mm", "reach-MP error (mm)", "mean")},
      {"failures_dropped", 2.0, count_metric(Better::lower)},
      {"offset", -1.5, MetricDeclaration{}},
      {"ceiling",
       0.25,
       {"s", {-std::numeric_limits<double>::infinity(), 4.0}, Better::lower, "", ""}},
  };
  store.complete_run(id, {}, metrics);
  EXPECT_EQ(run_metrics(store, id), metrics);
}

// A run stores what its task declared, read back as it was; a run without one has none.
TEST(ResultStore, ARunsTaskDeclarationIsStoredAndReadBack) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  RunRecord run = a_run();
  TaskDeclaration task;
  task.trajectory_columns = {"x", "y", "grip \"left\""};
  task.error_unit = "mm";
  task.error_scale = 1000.0;
  task.error_segments = {"reach", "post"};
  task.error_columns = {0, 1};
  task.decision_segment = "reach";
  task.decision_labels = {"b", "a"};
  task.relative_columns = {1};
  task.plot_horizontal = 1;
  task.plot_vertical = 0;
  task.outcome_metrics = {"touched"};
  task.failure_categories = {"missed the via point", "dropped"};
  run.task = task;
  const int64_t with_task = store.begin_run(run);
  const int64_t without = store.begin_run(a_run());
  ASSERT_TRUE(run_task(store, with_task));
  EXPECT_EQ(*run_task(store, with_task), task);
  EXPECT_FALSE(run_task(store, without));
}

// A run ends failed or interrupted; ending it as running or completed is a programming error.
TEST(ResultStore, ARunEndsFailedOrInterruptedOnly) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  const int64_t id = store.begin_run(a_run());
  EXPECT_THROW(store.end_run(id, RunStatus::completed, "no"), std::invalid_argument);
  store.end_run(id, RunStatus::interrupted, "Ctrl-C");
  RunSelection all;
  all.completed_only = false;
  const auto runs = select_runs(store, all);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].status, RunStatus::interrupted);
}

}  // namespace
}  // namespace corrmp
