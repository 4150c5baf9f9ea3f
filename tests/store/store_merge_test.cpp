// Merging shard databases (framework/store/store_merge.hpp): runs, trials,
// metrics and sweeps copied once, whatever the number of merges; unfinished
// runs left for later; a version-2 database migrated on open.
#include "store/store_merge.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"

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

TEST(StoreMerge, CopiesFinishedRunsOnceAndIsIdempotent) {
  TempDir dir;
  {
    ResultStore shard(dir.file("job-0.sqlite"));
    shard.execute(
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
  EXPECT_EQ(target.query_int("SELECT count(*) FROM runs"), 3);
  EXPECT_EQ(target.query_int("SELECT count(*) FROM trials"), 6);
  EXPECT_EQ(target.query_int("SELECT count(*) FROM metrics"), 3);
  EXPECT_EQ(target.query_int("SELECT count(*) FROM sweeps"), 1);
  // Trials and metrics follow their run to its new id.
  EXPECT_EQ(target.query_int("SELECT count(*) FROM trials t JOIN runs r ON r.id = t.run_id "
                             "WHERE r.experiment = 'b' AND r.job_index = 1"),
            2);
  EXPECT_EQ(target.query_text("SELECT axes FROM runs WHERE experiment = 'b'"), R"({"seed":"1"})");
}

TEST(StoreMerge, RefusesAMissingShardAndGivesOlderRunsAUid) {
  TempDir dir;
  ResultStore target(dir.file("all.sqlite"));
  EXPECT_THROW(merge_shard(target, dir.file("missing.sqlite")), StoreError);
  {
    ResultStore old(dir.file("old.sqlite"));
    add_run(old, "a", 0, true);
    // Back to version 2, as an older build wrote it.
    old.execute("DROP INDEX runs_uid; DROP INDEX runs_sweep; DROP TABLE sweeps;");
    old.execute(
        "ALTER TABLE runs DROP COLUMN uid; ALTER TABLE runs DROP COLUMN sweep_id; "
        "ALTER TABLE runs DROP COLUMN job_index; ALTER TABLE runs DROP COLUMN axes; "
        "PRAGMA user_version = 2");
  }
  EXPECT_EQ(merge_shard(target, dir.file("old.sqlite")).added, 1);
  EXPECT_EQ(merge_shard(target, dir.file("old.sqlite")).added, 0);
  EXPECT_EQ(target.query_int("SELECT count(*) FROM runs WHERE uid IS NOT NULL"), 1);
}

}  // namespace
}  // namespace corrmp
