// Merging shard databases (framework/store/store_merge.hpp): runs, trials,
// metrics and sweeps copied once, whatever the number of merges; unfinished
// runs left for later; a version-2 shard read as it is; all the shards in one
// transaction; a failure names the file it came from.
#include "store/store_merge.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "config/test_files.hpp"
#include "store/result_store.hpp"
#include "store/run_queries.hpp"
#include "support/refused_shard.hpp"
#include "support/store_sql.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

int64_t add_run(ResultStore& store, const std::string& experiment, int job, bool finish) {
  RunRecord run;
  run.experiment = experiment;
  run.config = "seed: 1\n";
  run.config_hash = "h";
  run.sweep_id = "s-1";
  run.job_index = job;
  run.axes = R"({"seed":"1"})";
  const int64_t id = store.begin_run(run);
  if (finish) {
    store.complete_run(id,
                       {TrialRecord{0, "{}", "push", "push", true, "", ""},
                        TrialRecord{1, "{}", "pull", "none", false, "missed", ""}},
                       {{"task_success_rate", 0.5}});
  }
  return id;
}

// Takes `store` back to schema version 2 (runs without uid or sweep), as an older build wrote it.
void downgrade_to_version_2(ResultStore& store) {
  testing::downgrade_to_version_3(store);
  testing::execute_sql(store, "DROP INDEX runs_uid; DROP INDEX runs_sweep; DROP TABLE sweeps;");
  testing::execute_sql(store,
                       "ALTER TABLE runs DROP COLUMN uid; ALTER TABLE runs DROP COLUMN sweep_id; "
                       "ALTER TABLE runs DROP COLUMN job_index; ALTER TABLE runs DROP COLUMN axes; "
                       "PRAGMA user_version = 2");
}

// The message of the StoreError merging `shards` into `target` throws ("" when none).
std::string merge_error(ResultStore& target, const std::vector<std::string>& shards) {
  try {
    merge_shards_into(target, shards);
  } catch (const StoreError& e) {
    return e.what();
  }
  return "";
}

TEST(StoreMerge, CopiesFinishedRunsOnceAndIsIdempotent) {
  TempDir dir;
  {
    ResultStore shard(dir.file("job-0.sqlite"));
    testing::execute_sql(
        shard,
        "INSERT INTO sweeps (id, name, created_at, jobs, manifest) VALUES ('s-1', 's', 't', 2, "
        "'m')");
    add_run(shard, "a", 0, true);
    add_run(shard, "a", 0, false);  // still running
  }
  {
    ResultStore shard(dir.file("job-1.sqlite"));
    add_run(shard, "b", 1, true);
  }
  ResultStore target(dir.file("all.sqlite"));
  add_run(target, "earlier", 0, true);  // ids in the target differ from the shards'

  MergeCounts first = merge_shard(target, dir.file("job-0.sqlite"));
  EXPECT_EQ(first.added, 1);
  EXPECT_EQ(first.unfinished, 1);
  EXPECT_EQ(merge_shard(target, dir.file("job-1.sqlite")).added, 1);
  for (const char* shard : {"job-0.sqlite", "job-1.sqlite"}) {
    const MergeCounts again = merge_shard(target, dir.file(shard));
    EXPECT_EQ(again.added, 0);
    EXPECT_EQ(again.present, 1);
  }
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM runs"), 3);
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM trials"), 6);
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM metrics"), 3);
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM sweeps"), 1);
  // Trials and metrics follow their run to its new id.
  EXPECT_EQ(testing::query_int(target,
                               "SELECT count(*) FROM trials t JOIN runs r ON r.id = t.run_id "
                               "WHERE r.experiment = 'b' AND r.job_index = 1"),
            2);
  EXPECT_EQ(testing::query_text(target, "SELECT axes FROM runs WHERE experiment = 'b'"),
            R"({"seed":"1"})");
}

TEST(StoreMerge, RefusesAMissingShardAndGivesOlderRunsAUid) {
  TempDir dir;
  ResultStore target(dir.file("all.sqlite"));
  EXPECT_THROW(merge_shard(target, dir.file("missing.sqlite")), StoreError);
  {
    ResultStore old(dir.file("old.sqlite"));
    add_run(old, "a", 0, true);
    downgrade_to_version_2(old);
  }
  EXPECT_EQ(merge_shard(target, dir.file("old.sqlite")).added, 1);
  EXPECT_EQ(merge_shard(target, dir.file("old.sqlite")).added, 0);
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM runs WHERE uid IS NOT NULL"), 1);
}

// A merged run keeps its metrics' declarations and its task's declaration.
TEST(StoreMerge, ARunsDeclarationsFollowItIntoTheTarget) {
  TempDir dir;
  TaskDeclaration task;
  task.error_unit = "mm";
  task.decision_labels = {"b", "a"};
  const std::vector<MetricRecord> metrics = {
      {"reach_mp_error_mean_mm", 2.5, error_statistic("mm", "reach-MP error (mm)", "mean")},
      {"task_success_rate", 0.5, rate_metric(Better::higher)}};
  {
    ResultStore shard(dir.file("job-0.sqlite"));
    add_run(shard, "before", 0, true);  // a run without a task
    RunRecord run;
    run.experiment = "reach";
    run.config = "seed: 2\n";
    run.config_hash = "h";
    run.task = task;
    const int64_t id = shard.begin_run(run);
    shard.complete_run(id, {}, metrics);
  }
  ResultStore target(dir.file("all.sqlite"));
  add_run(target, "earlier", 0, true);
  EXPECT_EQ(merge_shard(target, dir.file("job-0.sqlite")).added, 2);
  RunSelection reach;
  reach.experiments = {"reach"};
  const auto runs = select_runs(target, reach);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].id, 3);
  EXPECT_EQ(run_metrics(target, runs[0].id), metrics);
  ASSERT_TRUE(run_task(target, runs[0].id));
  EXPECT_EQ(*run_task(target, runs[0].id), task);
  EXPECT_FALSE(run_task(target, 2));
}

// A version-2 shard upgraded after it was merged (opened as a result store, as `report --db`
// does) gives its runs the uids the merge made from their fields: merging it again adds nothing.
TEST(StoreMerge, AnOldShardUpgradedAfterItsMergeIsNotMergedAgain) {
  TempDir dir;
  const std::string old_path = dir.file("old.sqlite");
  {
    ResultStore old(old_path);
    add_run(old, "a", 0, true);
    add_run(old, "b", 1, true);
    downgrade_to_version_2(old);
  }
  ResultStore target(dir.file("all.sqlite"));
  EXPECT_EQ(merge_shard(target, old_path).added, 2);
  { ResultStore upgraded(old_path); }
  const MergeCounts again = merge_shard(target, old_path);
  EXPECT_EQ(again.added, 0);
  EXPECT_EQ(again.present, 2);
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM runs"), 2);
}

// All the shards go in one transaction: one that fails while it is copied (here a run the
// target's schema refuses, which the checks before copying do not look at) leaves the target
// as it was, and the error names that shard.
TEST(StoreMerge, AShardThatFailsWhileCopiedLeavesTheTargetAsItWas) {
  TempDir dir;
  {
    ResultStore good(dir.file("good.sqlite"));
    add_run(good, "a", 0, true);
  }
  testing::write_shard_the_target_refuses(dir.file("bad.sqlite"));
  const std::vector<std::string> shards = {dir.file("good.sqlite"), dir.file("bad.sqlite")};
  check_shards(shards, dir.file("all.sqlite"));
  ResultStore target(dir.file("all.sqlite"));
  const std::string message = merge_error(target, shards);
  EXPECT_EQ(message.rfind(target.path() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("CHECK constraint failed"), std::string::npos) << message;
  EXPECT_NE(message.find(dir.file("bad.sqlite")), std::string::npos) << message;
  EXPECT_NE(message.find("nothing was merged"), std::string::npos) << message;
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM runs"), 0);
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM trials"), 0);
}

// A failure writing the target names the target, not the shard being read; one reading a shard
// names the shard. Either way nothing is merged.
TEST(StoreMerge, AFailureNamesTheTargetOrTheShardItCameFrom) {
  TempDir dir;
  {
    ResultStore good(dir.file("good.sqlite"));
    add_run(good, "a", 0, true);
  }
  ResultStore target(dir.file("all.sqlite"));
  testing::execute_sql(
      target,
      "CREATE TRIGGER refuse BEFORE INSERT ON trials BEGIN SELECT RAISE(ABORT, 'target says "
      "no'); END");
  const std::string refused = merge_error(target, {dir.file("good.sqlite")});
  EXPECT_EQ(refused.rfind(target.path() + ": ", 0), 0u) << refused;
  EXPECT_NE(refused.find("target says no"), std::string::npos) << refused;
  EXPECT_NE(refused.find("nothing was merged"), std::string::npos) << refused;
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM runs"), 0);

  testing::execute_sql(target, "DROP TRIGGER refuse");
  const std::string missing =
      merge_error(target, {dir.file("good.sqlite"), dir.file("missing.sqlite")});
  EXPECT_EQ(missing.rfind(dir.file("missing.sqlite") + ": ", 0), 0u) << missing;
  EXPECT_NE(missing.find("nothing was merged"), std::string::npos) << missing;
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM runs"), 0);
}

// A shard whose writer still has it open keeps its newest rows in the write-ahead log beside
// it: the merge reads them through that log.
TEST(StoreMerge, AShardStillOpenByItsWriterIsReadThroughItsLog) {
  TempDir dir;
  ResultStore writer(dir.file("job-0.sqlite"));
  add_run(writer, "a", 0, true);
  ASSERT_TRUE(std::filesystem::exists(dir.file("job-0.sqlite-wal")));
  ResultStore target(dir.file("all.sqlite"));
  EXPECT_EQ(merge_shard(target, dir.file("job-0.sqlite")).added, 1);
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM trials"), 2);
}

// SQLite keeps the log beside the file a link points to: a shard named through a link (its
// schema checkpointed, its runs still in the log) is read through that log too.
TEST(StoreMerge, AShardNamedThroughALinkIsReadThroughItsLog) {
  TempDir dir;
  ResultStore writer(dir.file("job-0.sqlite"));
  testing::execute_sql(writer, "PRAGMA wal_checkpoint(TRUNCATE)");
  add_run(writer, "a", 0, true);
  std::filesystem::create_directories(dir.file("links"));
  std::filesystem::create_symlink(dir.file("job-0.sqlite"), dir.file("links/job-0.sqlite"));
  ResultStore target(dir.file("all.sqlite"));
  EXPECT_EQ(merge_shard(target, dir.file("links/job-0.sqlite")).added, 1);
  EXPECT_EQ(testing::query_int(target, "SELECT count(*) FROM trials"), 2);
}

}  // namespace
}  // namespace corrmp
