// Merging result databases (store_merge.hpp).
#include "store/store_merge.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <memory>

#include "core/path_checks.hpp"
#include "store/legacy_metrics.hpp"
#include "store/metric_rows.hpp"
#include "store/run_uid.hpp"
#include "store/shard_reader.hpp"
#include "store/statement.hpp"
#include "store/store_access.hpp"
#include "store/task_rows.hpp"

namespace corrmp {

namespace {

// The runs' columns copied as they are (the uid is handled apart).
const std::vector<std::string> kRunColumns = {
    "experiment",  "config",     "config_hash", "seed",    "status", "started_at",
    "finished_at", "git_commit", "git_dirty",   "out_dir", "host",   "pid",
    "failure",     "sweep_id",   "job_index",   "axes"};
const std::vector<std::string> kTrialColumns = {
    "trial", "scenario", "expected_action", "chosen_action", "success", "failure", "details"};
const std::vector<std::string> kMetricColumns = {"name", "value"};  // then the declaration
const std::vector<std::string> kSweepColumns = {"id", "name", "created_at", "jobs", "manifest"};

// The shard's columns for a SELECT list, NULL for those its (older) schema lacks.
std::string select_list(const ShardReader& shard, const std::string& table,
                        const std::vector<std::string>& columns) {
  std::vector<std::string> listed;
  for (const auto& column : columns) listed.push_back(shard.column_or_null(table, column));
  return fmt::format("{}", fmt::join(listed, ", "));
}

std::string insert_sql(const std::string& table, const std::vector<std::string>& columns,
                       const std::string& leading_column = "") {
  std::string names = leading_column.empty() ? "" : leading_column + ", ";
  std::string values = leading_column.empty() ? "" : "?, ";
  for (size_t i = 0; i < columns.size(); ++i) {
    names += (i > 0 ? ", " : "") + columns[i];
    values += i > 0 ? ", ?" : "?";
  }
  return fmt::format("INSERT INTO {} ({}) VALUES ({})", table, names, values);
}

MergeCounts copy_shard(ResultStore& target, ShardReader& shard) {
  sqlite3* db = StoreAccess::connection(target);
  if (shard.has_table("sweeps")) {
    ShardQuery sweeps(shard,
                      "SELECT " + select_list(shard, "sweeps", kSweepColumns) + " FROM sweeps");
    Statement insert(db,
                     "INSERT OR IGNORE INTO sweeps (id, name, created_at, jobs, manifest) VALUES "
                     "(?, ?, ?, ?, ?)");
    while (sweeps.step()) {
      for (int i = 0; i < 5; ++i) insert.bind_column(i + 1, sweeps.row(), i);
      insert.run();
    }
  }
  // Columns 0 and 1 are the run's id and uid, then kRunColumns.
  ShardQuery runs(shard, fmt::format("SELECT id, {}, {} FROM runs ORDER BY id",
                                     shard.column_or_null("runs", "uid"),
                                     select_list(shard, "runs", kRunColumns)));
  const auto at = [](const std::string& column) {
    return 2 + static_cast<int>(std::find(kRunColumns.begin(), kRunColumns.end(), column) -
                                kRunColumns.begin());
  };
  std::vector<int> identity;  // the columns of kRunIdentityColumns
  for (const auto& column : kRunIdentityColumns)
    identity.push_back(column == "id" ? 0 : at(column));
  ShardQuery trials(shard, fmt::format("SELECT {} FROM trials WHERE run_id = ? ORDER BY rowid",
                                       select_list(shard, "trials", kTrialColumns)));
  // A shard written before metrics were declared gets the declarations a migration gives them.
  const bool declared = shard.column_or_null("metrics", "unit") != "NULL";
  ShardQuery metrics(
      shard, fmt::format("SELECT {}{}{} FROM metrics WHERE run_id = ? ORDER BY rowid",
                         select_list(shard, "metrics", kMetricColumns), declared ? ", " : "",
                         declared ? kDeclarationColumns : ""));
  std::unique_ptr<ShardQuery> task;  // the run's task declaration (none in an older shard)
  if (shard.has_table("run_tasks")) {
    task = std::make_unique<ShardQuery>(shard,
                                        fmt::format("SELECT {} FROM run_tasks WHERE run_id = ?",
                                                    select_list(shard, "run_tasks", kTaskColumns)));
  }
  Statement present(db, "SELECT count(*) FROM runs WHERE uid = ?");
  std::vector<std::string> run_columns = kRunColumns;
  run_columns.push_back("uid");
  Statement copy_run(db, insert_sql("runs", run_columns));
  Statement copy_trial(db, insert_sql("trials", kTrialColumns, "run_id"));
  Statement copy_metric(db, fmt::format("INSERT INTO metrics (run_id, name, value, {}) VALUES "
                                        "(?, ?, ?, ?, ?, ?, ?, ?, ?)",
                                        kDeclarationColumns));
  Statement copy_task(db, insert_sql("run_tasks", kTaskColumns, "run_id"));

  MergeCounts counts;
  while (runs.step()) {
    const Statement& run = runs.row();
    if (run.column_text(at("status")) == "running") {
      ++counts.unfinished;
      continue;
    }
    const std::string stored_uid = run.column_text(1);
    std::string uid = stored_uid;
    if (uid.empty()) {  // a shard written before runs had a uid
      std::vector<std::string> values;
      for (int column : identity) values.push_back(run.column_text(column));
      uid = derived_run_uid(values);
    }
    present.bind(1, uid);
    const bool known = present.step() && present.column_int(0) > 0;
    present.reset();
    if (known) {
      ++counts.present;
      continue;
    }
    for (size_t i = 0; i < kRunColumns.size(); ++i) {
      copy_run.bind_column(static_cast<int>(i) + 1, run, static_cast<int>(i) + 2);
    }
    copy_run.bind(static_cast<int>(kRunColumns.size()) + 1, uid).run();
    const int64_t new_id = sqlite3_last_insert_rowid(db);
    const int64_t old_id = run.column_int(0);
    trials.bind(1, old_id);
    while (trials.step()) {
      copy_trial.bind(1, new_id);
      for (size_t i = 0; i < kTrialColumns.size(); ++i) {
        copy_trial.bind_column(static_cast<int>(i) + 2, trials.row(), static_cast<int>(i));
      }
      copy_trial.run();
    }
    trials.reset();
    metrics.bind(1, old_id);
    while (metrics.step()) {
      const Statement& metric = metrics.row();
      copy_metric.bind(1, new_id).bind_column(2, metric, 0).bind_column(3, metric, 1);
      if (declared) {
        for (int i = 0; i < kDeclarationColumnCount; ++i) {
          copy_metric.bind_column(4 + i, metric, 2 + i);
        }
      } else {
        bind_declaration(copy_metric, 4, inferred_declaration(metric.column_text(0)));
      }
      copy_metric.run();
    }
    metrics.reset();
    if (task) {
      task->bind(1, old_id);
      if (task->step()) {
        copy_task.bind(1, new_id);
        for (size_t i = 0; i < kTaskColumns.size(); ++i) {
          copy_task.bind_column(static_cast<int>(i) + 2, task->row(), static_cast<int>(i));
        }
        copy_task.run();
      }
      task->reset();
    }
    ++counts.added;
  }
  return counts;
}

void refuse_the_target(const std::string& shard, const std::string& target_path) {
  if (same_file(shard, target_path)) {
    throw ShardError(fmt::format(
        "{}: is the database being merged into ({}): merge into another file", shard, target_path));
  }
}

// `message` of an error of `target` without the target's name in front, as the target's own
// calls give it (its path) or its statements do (SQLite's name for the file).
std::string without_target_name(ResultStore& target, const std::string& message) {
  const char* file = sqlite3_db_filename(StoreAccess::connection(target), "main");
  for (const std::string& name : {target.path(), std::string(file != nullptr ? file : "")}) {
    if (!name.empty() && message.rfind(name + ": ", 0) == 0) return message.substr(name.size() + 2);
  }
  return message;
}

}  // namespace

void check_shards(const std::vector<std::string>& shards, const std::string& target_path) {
  for (const auto& shard : shards) {
    refuse_the_target(shard, target_path);
    ShardReader(shard).check_integrity();
  }
}

std::vector<MergeCounts> merge_shards_into(ResultStore& target,
                                           const std::vector<std::string>& shards) {
  std::vector<MergeCounts> counts;
  std::string merging;  // the shard being copied when the target fails
  try {
    target.transaction([&] {
      counts.clear();
      for (const auto& shard : shards) {
        merging = shard;
        refuse_the_target(shard, target.path());
        ShardReader reader(shard);
        counts.push_back(copy_shard(target, reader));
      }
      merging.clear();  // a failed commit is the target's alone
    });
  } catch (const ShardError& e) {
    throw StoreError(fmt::format("{}; nothing was merged", e.what()));
  } catch (const StoreError& e) {
    throw StoreError(fmt::format("{}: {}{}; nothing was merged", target.path(),
                                 merging.empty() ? "" : "while merging " + merging + ": ",
                                 without_target_name(target, e.what())));
  }
  return counts;
}

MergeCounts merge_shard(ResultStore& target, const std::string& shard) {
  check_shards({shard}, target.path());
  return merge_shards_into(target, {shard}).front();
}

}  // namespace corrmp
