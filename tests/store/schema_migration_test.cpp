// Tests of opening a database an older build wrote: tests/store/fixtures/schema_v3.sqlite, written
// by run_experiment before metrics and tasks were declared (schema 3: two tiny corridor_pc runs
// and a curves_demo run). Its metrics get the declarations their names imply, its values stay as
// they were, its runs have no task declaration, and merging it as a shard gives what migrating it
// in place gives.
#include <gtest/gtest.h>

#include <filesystem>

#include "config/test_files.hpp"
#include "store/result_store.hpp"
#include "store/run_queries.hpp"
#include "store/shard_reader.hpp"
#include "store/store_merge.hpp"
#include "support/store_sql.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

// A copy of the fixture (opening a database migrates it in place).
std::string copy_of_schema_3(const TempDir& dir) {
  const std::string copy = dir.file("schema_v3.sqlite");
  std::filesystem::copy_file(std::string(STORE_FIXTURES) + "/schema_v3.sqlite", copy);
  return copy;
}

const MetricRecord& named(const std::vector<MetricRecord>& metrics, const std::string& name) {
  for (const auto& metric : metrics) {
    if (metric.name == name) return metric;
  }
  throw std::runtime_error("no metric " + name);
}

TEST(SchemaMigration, ASchema3DatabaseGetsItsMetricsDeclaredAndKeepsItsValues) {
  TempDir dir;
  const std::string path = copy_of_schema_3(dir);
  std::vector<std::pair<std::string, double>> written;  // every metric as the old build wrote it
  {
    ShardReader fixture(path);  // read-only: not migrated
    ShardQuery metrics(fixture, "SELECT name, value FROM metrics ORDER BY rowid");
    while (metrics.step()) {
      written.emplace_back(metrics.row().column_text(0), metrics.row().column_double(1));
    }
  }
  ResultStore store(path);
  EXPECT_EQ(testing::query_int(store, "PRAGMA user_version"), ResultStore::kSchemaVersion);
  RunSelection all;
  const auto runs = select_runs(store, all);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].experiment, "corridor_pc");
  EXPECT_EQ(runs[2].experiment, "curves_demo");
  EXPECT_EQ(runs[0].status, RunStatus::completed);

  const auto corridor = run_metrics(store, runs[0].id);
  ASSERT_EQ(corridor.size(), 17u);
  EXPECT_EQ(corridor[0].name, "demonstrations_train");  // in the order the run recorded them
  EXPECT_EQ(corridor[0].value, 10.0);
  EXPECT_EQ(corridor[0].declaration, count_metric(Better::neither));
  EXPECT_DOUBLE_EQ(named(corridor, "task_success_rate").value, 1.0 / 6.0);
  EXPECT_EQ(named(corridor, "task_success_rate").declaration, rate_metric(Better::higher));
  EXPECT_EQ(named(corridor, "cor_mp_error_mean_cm").declaration,
            error_statistic("cm", "cor-MP error mean / max (cm)", "mean"));
  EXPECT_EQ(named(corridor, "post_mp_error_max_cm").declaration,
            error_statistic("cm", "post-MP error mean / max (cm)", "max"));
  EXPECT_EQ(named(corridor, "expected_pull").declaration, count_metric(Better::neither));
  const auto curves = run_metrics(store, runs[2].id);
  EXPECT_EQ(named(curves, "full_error_mean").declaration,
            error_statistic("", "full error mean / max (held-out)", "mean"));

  std::vector<std::pair<std::string, double>> migrated;
  for (const auto& run : runs) {
    for (const auto& metric : run_metrics(store, run.id)) {
      migrated.emplace_back(metric.name, metric.value);
    }
  }
  EXPECT_EQ(migrated, written);  // bit for bit

  for (const auto& run : runs) EXPECT_FALSE(run_task(store, run.id)) << run.id;
  const auto counts = run_decision_counts(store, runs[0].id);
  ASSERT_FALSE(counts.empty());
  EXPECT_EQ(run_trials(store, runs[0].id).size(), 6u);
}

TEST(SchemaMigration, MergingASchema3ShardGivesWhatMigratingItGives) {
  TempDir dir;
  const std::string shard = dir.file("shard.sqlite");
  std::filesystem::copy_file(std::string(STORE_FIXTURES) + "/schema_v3.sqlite", shard);
  ResultStore merged(dir.file("merged.sqlite"));
  EXPECT_EQ(merge_shard(merged, shard).added, 3);
  ResultStore migrated(copy_of_schema_3(dir));
  for (int64_t id = 1; id <= 3; ++id) {
    EXPECT_EQ(run_metrics(merged, id), run_metrics(migrated, id)) << id;
    EXPECT_FALSE(run_task(merged, id)) << id;
  }
}

}  // namespace
}  // namespace corrmp
