// run_experiment merge on inputs that must not be merged or changed: a shard that is not a
// result database or has a damaged page merges nothing and is named; the shards are only read
// (an old schema is not upgraded, a refused one gains no -wal or -shm); a target that is one of
// the shards, or lies below a file, is refused at once; a failed merge leaves no new target.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/test_files.hpp"
#include "store/result_store.hpp"
#include "support/refused_shard.hpp"
#include "support/store_sql.hpp"

namespace corrmp {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

struct MergeOutcome {
  int exit_code;
  std::string out;
  double seconds;
};

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

MergeOutcome merge(const TempDir& dir, const std::string& shards, const std::string& db) {
  const std::string log = dir.file("merge.txt");
  const std::string command =
      std::string(RUN_EXPERIMENT_BIN) + " merge " + shards + " --db " + db + " >" + log + " 2>&1";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, bytes_of(log), seconds};
}

int lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

// A shard with one completed run of `trials` trials, each with a scenario of `scenario_bytes`.
std::string make_shard(const TempDir& dir, const std::string& name, int trials = 2,
                       size_t scenario_bytes = 2) {
  const std::string path = dir.file(name);
  ResultStore shard(path);
  RunRecord run;
  run.experiment = "tiny";
  run.config = "seed: 1\n";
  run.config_hash = "h";
  const int64_t id = shard.begin_run(run);
  std::vector<TrialRecord> records;
  for (int i = 0; i < trials; ++i) {
    records.push_back({i, std::string(scenario_bytes, 'x'), "push", "push", true, "", ""});
  }
  shard.complete_run(id, records, {{"task_success_rate", 1.0}});
  return path;
}

int64_t completed_runs(const std::string& db) {
  ResultStore store(db);
  return testing::query_int(store, "SELECT count(*) FROM runs WHERE status = 'completed'");
}

TEST(MergeCommand, AShardThatIsNotAResultDatabaseMergesNothingAndIsLeftAsItWas) {
  TempDir dir;
  const std::string good = make_shard(dir, "good.sqlite");
  const std::string foreign = dir.file("foreign.sqlite");
  {
    ResultStore store(foreign);
    testing::execute_sql(
        store,
        "DROP TABLE trials; DROP TABLE metrics; DROP TABLE runs; "
        "CREATE TABLE runs (name TEXT); CREATE TABLE trials (x INTEGER); "
        "CREATE TABLE metrics (y REAL); INSERT INTO runs VALUES ('someone else''s');"
        "PRAGMA journal_mode=DELETE");
  }
  const std::string before = bytes_of(foreign);
  const std::string target = dir.file("t.sqlite");
  const MergeOutcome outcome = merge(dir, good + " " + foreign, target);
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_EQ(lines(outcome.out), 1) << outcome.out;
  EXPECT_EQ(outcome.out, "run_experiment merge: " + foreign +
                             ": not a result database to merge (its runs table has no column "
                             "'id')\n");
  EXPECT_FALSE(fs::exists(target)) << "nothing merged, not even the good shard";
  EXPECT_TRUE(bytes_of(foreign) == before) << "the foreign shard was changed";
  EXPECT_FALSE(fs::exists(foreign + "-wal"));
  EXPECT_FALSE(fs::exists(foreign + "-shm"));
}

TEST(MergeCommand, AShardWithADamagedPageIsNamedAndNothingIsMerged) {
  TempDir dir;
  const std::string good = make_shard(dir, "good.sqlite");
  const std::string damaged = make_shard(dir, "damaged.sqlite", 200, 1000);
  ASSERT_GT(fs::file_size(damaged), 20 * 4096u);
  {
    std::fstream file(damaged, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(10 * 4096);
    const std::string garbage(4096, '\x55');
    file.write(garbage.data(), static_cast<std::streamsize>(garbage.size()));
  }
  const std::string before = bytes_of(damaged);
  const std::string target = dir.file("t.sqlite");
  const MergeOutcome outcome = merge(dir, good + " " + damaged, target);
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_EQ(lines(outcome.out), 1) << outcome.out;
  EXPECT_EQ(outcome.out.rfind("run_experiment merge: " + damaged + ": ", 0), 0u) << outcome.out;
  EXPECT_EQ(outcome.out.find(target), std::string::npos) << outcome.out;
  EXPECT_FALSE(fs::exists(target) && completed_runs(target) > 0) << "nothing merged";
  EXPECT_TRUE(bytes_of(damaged) == before) << "the damaged shard was changed";
}

// An older schema (version 2: no uid) is read as it is, not upgraded; merging it twice adds its
// run once. A refused shard gets no -wal or -shm beside it.
TEST(MergeCommand, ShardsAreOnlyReadNeverChanged) {
  TempDir dir;
  const std::string old = make_shard(dir, "old.sqlite");
  {
    ResultStore store(old);
    testing::downgrade_to_version_3(store);
    testing::execute_sql(
        store,
        "DROP INDEX runs_uid; DROP INDEX runs_sweep; DROP TABLE sweeps; "
        "ALTER TABLE runs DROP COLUMN uid; ALTER TABLE runs DROP COLUMN sweep_id; "
        "ALTER TABLE runs DROP COLUMN job_index; ALTER TABLE runs DROP COLUMN axes; "
        "PRAGMA user_version = 2; PRAGMA journal_mode=DELETE");
  }
  const std::string before = bytes_of(old);
  const std::string target = dir.file("t.sqlite");
  for (int merges = 0; merges < 2; ++merges) {
    const MergeOutcome outcome = merge(dir, old, target);
    ASSERT_EQ(outcome.exit_code, 0) << outcome.out;
    EXPECT_TRUE(bytes_of(old) == before) << "the old shard was changed by merge " << merges;
    EXPECT_FALSE(fs::exists(old + "-wal"));
    EXPECT_FALSE(fs::exists(old + "-shm"));
  }
  EXPECT_EQ(completed_runs(target), 1);

  const std::string truncated = make_shard(dir, "truncated.sqlite", 200, 1000);
  fs::resize_file(truncated, 2 * 4096);
  const std::string cut = bytes_of(truncated);
  const MergeOutcome refused = merge(dir, truncated, target);
  EXPECT_EQ(refused.exit_code, 2) << refused.out;
  EXPECT_EQ(lines(refused.out), 1) << refused.out;
  EXPECT_NE(refused.out.find(truncated + ": "), std::string::npos) << refused.out;
  EXPECT_TRUE(bytes_of(truncated) == cut) << "the truncated shard was changed";
  EXPECT_FALSE(fs::exists(truncated + "-wal"));
  EXPECT_FALSE(fs::exists(truncated + "-shm"));
}

TEST(MergeCommand, MergingIntoOneOfTheShardsIsRefusedAtOnce) {
  TempDir dir;
  const std::string shard = make_shard(dir, "a.sqlite");
  const std::string other = make_shard(dir, "b.sqlite");
  fs::create_directories(dir.file("sub"));
  fs::create_symlink(shard, dir.file("link.sqlite"));
  const std::string before = bytes_of(shard);
  for (const std::string& target :
       {shard, dir.file("sub/../a.sqlite"), dir.file("./a.sqlite"), dir.file("link.sqlite")}) {
    const MergeOutcome outcome = merge(dir, other + " " + shard, target);
    EXPECT_EQ(outcome.exit_code, 2) << target << ": " << outcome.out;
    EXPECT_EQ(outcome.out, "run_experiment merge: " + shard +
                               ": is the database being merged into (" + target +
                               "): merge into another file\n");
    // Catches a wait for the target's lock (the 60 s busy timeout), not a slow machine.
    EXPECT_LT(outcome.seconds, 40.0) << "refused at once, not after a lock's timeout";
    EXPECT_TRUE(bytes_of(shard) == before) << target << ": the shard was changed";
  }
}

// A shard that passes the checks but whose run the target refuses (a status its schema does not
// allow): the line names the target, and a target this merge made is not left behind, nor the
// folder made for it; a target that was there keeps its runs.
TEST(MergeCommand, AMergeTheTargetRefusesLeavesNoNewTargetBehind) {
  TempDir dir;
  const std::string good = make_shard(dir, "good.sqlite");
  const std::string refused = dir.file("refused.sqlite");
  testing::write_shard_the_target_refuses(refused);
  const std::string target = dir.file("new/t.sqlite");
  const MergeOutcome outcome = merge(dir, good + " " + refused, target);
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_EQ(lines(outcome.out), 1) << outcome.out;
  EXPECT_EQ(outcome.out.rfind("run_experiment merge: " + target + ": ", 0), 0u) << outcome.out;
  EXPECT_FALSE(fs::exists(dir.file("new"))) << "the new target was left behind";

  const std::string existing = make_shard(dir, "existing.sqlite");
  EXPECT_EQ(merge(dir, good + " " + refused, existing).exit_code, 2);
  EXPECT_EQ(completed_runs(existing), 1);
}

TEST(MergeCommand, ATargetBelowAFileIsRefusedNamingThePath) {
  TempDir dir;
  const std::string shard = make_shard(dir, "a.sqlite");
  const std::string file = dir.write("afile", "in the way\n");
  const MergeOutcome outcome = merge(dir, shard, file + "/x.sqlite");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_EQ(outcome.out, "run_experiment merge: " + file + "/x.sqlite: cannot make its folder: '" +
                             file + "' is a file, not a folder\n");
  EXPECT_EQ(bytes_of(file), "in the way\n");
}

}  // namespace
}  // namespace corrmp
