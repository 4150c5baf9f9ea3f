// Merging result databases (store_merge.hpp).
#include "store/store_merge.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "store/statement.hpp"

namespace corrmp {

namespace {

constexpr const char* kRunColumns =
    "experiment, config, config_hash, seed, status, started_at, finished_at, git_commit, "
    "git_dirty, out_dir, host, pid, failure, uid, sweep_id, job_index, axes";

// Detaches the shard whatever happens.
class Attached {
 public:
  Attached(ResultStore& store, const std::string& path) : store_(store) {
    Statement attach(store.handle(), "ATTACH DATABASE ? AS shard");
    attach.bind(1, path).run();
  }
  ~Attached() { sqlite3_exec(store_.handle(), "DETACH DATABASE shard", nullptr, nullptr, nullptr); }
  Attached(const Attached&) = delete;
  Attached& operator=(const Attached&) = delete;

 private:
  ResultStore& store_;
};

}  // namespace

void check_shard(const std::string& shard) {
  if (!std::filesystem::is_regular_file(shard)) {
    throw StoreError(fmt::format("{}: no such database file", shard));
  }
  sqlite3* db = nullptr;
  int code = sqlite3_open_v2(shard.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
  int64_t version = 0, tables = 0;
  // One row: the schema version and how many of the tables every version has are there.
  const char* query_text =
      "SELECT (SELECT user_version FROM pragma_user_version), (SELECT count(*) FROM "
      "sqlite_master WHERE type = 'table' AND name IN ('runs', 'trials', 'metrics'))";
  if (code == SQLITE_OK) {
    sqlite3_stmt* query = nullptr;
    code = sqlite3_prepare_v2(db, query_text, -1, &query, nullptr);
    if (code == SQLITE_OK && (code = sqlite3_step(query)) == SQLITE_ROW) {
      version = sqlite3_column_int64(query, 0);
      tables = sqlite3_column_int64(query, 1);
      code = SQLITE_OK;
    }
    sqlite3_finalize(query);
  }
  sqlite3_close(db);
  if (code != SQLITE_OK) {
    throw StoreError(
        fmt::format("{}: not a result database to merge ({})", shard, sqlite3_errstr(code)));
  }
  if (tables < 3) {
    throw StoreError(fmt::format(
        "{}: not a result database to merge (it lacks the runs, trials or metrics table)", shard));
  }
  if (version > ResultStore::kSchemaVersion) {
    throw StoreError(fmt::format(
        "{}: written by a newer version of this program (schema {}, this one reads up to {})",
        shard, version, ResultStore::kSchemaVersion));
  }
}

MergeCounts merge_shard(ResultStore& target, const std::string& shard) {
  check_shard(shard);
  // Opening it through the store checks its schema and brings it up to date.
  { ResultStore check(shard); }
  MergeCounts counts;
  Attached attached(target, shard);
  target.transaction([&] {
    target.execute(
        "INSERT OR IGNORE INTO sweeps (id, name, created_at, jobs, manifest) "
        "SELECT id, name, created_at, jobs, manifest FROM shard.sweeps");
    Statement runs(target.handle(), "SELECT id, uid, status FROM shard.runs ORDER BY id");
    Statement present(target.handle(), "SELECT count(*) FROM main.runs WHERE uid = ?");
    Statement copy_run(target.handle(),
                       fmt::format("INSERT INTO main.runs ({0}) SELECT {0} FROM shard.runs "
                                   "WHERE id = ?",
                                   kRunColumns));
    Statement copy_trials(target.handle(),
                          "INSERT INTO main.trials (run_id, trial, scenario, expected_action, "
                          "chosen_action, success, failure, details) SELECT ?, trial, scenario, "
                          "expected_action, chosen_action, success, failure, details FROM "
                          "shard.trials WHERE run_id = ? ORDER BY rowid");
    Statement copy_metrics(target.handle(),
                           "INSERT INTO main.metrics (run_id, name, value) SELECT ?, name, value "
                           "FROM shard.metrics WHERE run_id = ? ORDER BY rowid");
    while (runs.step()) {
      const int64_t id = runs.column_int(0);
      if (runs.column_text(2) == "running") {
        ++counts.unfinished;
        continue;
      }
      present.bind(1, runs.column_text(1));
      const bool known = present.step() && present.column_int(0) > 0;
      present.reset();
      if (known) {
        ++counts.present;
        continue;
      }
      copy_run.bind(1, id).run();
      const int64_t new_id = sqlite3_last_insert_rowid(target.handle());
      copy_trials.bind(1, new_id).bind(2, id).run();
      copy_metrics.bind(1, new_id).bind(2, id).run();
      ++counts.added;
    }
  });
  return counts;
}

}  // namespace corrmp
