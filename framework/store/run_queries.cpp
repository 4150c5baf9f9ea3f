// Reading recorded runs back (run_queries.hpp).
#include "store/run_queries.hpp"

#include <fmt/format.h>

#include "store/metric_rows.hpp"
#include "store/statement.hpp"
#include "store/store_access.hpp"
#include "store/task_rows.hpp"

namespace corrmp {

namespace {

// "?, ?, ?" for `count` bound parameters.
std::string placeholders(size_t count) {
  std::string text;
  for (size_t i = 0; i < count; ++i) text += i == 0 ? "?" : ", ?";
  return text;
}

bool table_has_column(sqlite3* db, const std::string& table, const std::string& column) {
  Statement info(db, "SELECT 1 FROM pragma_table_info(?) WHERE name = ?");
  info.bind(1, table).bind(2, column);
  return info.step();
}

// A JSON object's members as text (strings unquoted), by SQLite's json_each.
std::map<std::string, std::string> json_object_members(sqlite3* db, const std::string& json) {
  std::map<std::string, std::string> members;
  if (json.empty()) return members;
  Statement each(db, "SELECT key, value FROM json_each(?)");
  each.bind(1, json);
  while (each.step()) members[each.column_text(0)] = each.column_text(1);
  return members;
}

}  // namespace

bool records_sweeps(ResultStore& store) {
  sqlite3* db = StoreAccess::connection(store);
  return table_has_column(db, "runs", "sweep_id") && table_has_column(db, "runs", "job_index") &&
         table_has_column(db, "runs", "axes");
}

std::vector<StoredRun> select_runs(ResultStore& store, const RunSelection& selection) {
  sqlite3* db = StoreAccess::connection(store);
  const bool sweeps_recorded = records_sweeps(store);
  if (!selection.sweeps.empty() && !sweeps_recorded) {
    throw StoreError(
        fmt::format("'{}' records no sweeps (written before runs had a sweep id)", store.path()));
  }
  std::string where = selection.completed_only ? "WHERE status = 'completed'" : "WHERE 1";
  if (!selection.experiments.empty()) {
    where += " AND experiment IN (" + placeholders(selection.experiments.size()) + ")";
  }
  if (!selection.runs.empty()) where += " AND id IN (" + placeholders(selection.runs.size()) + ")";
  if (!selection.sweeps.empty()) {
    where += " AND sweep_id IN (" + placeholders(selection.sweeps.size()) + ")";
  }
  const std::string sweep_columns =
      sweeps_recorded ? "sweep_id, job_index, axes" : "NULL, NULL, NULL";
  std::string sql = "SELECT id, experiment, status, config, coalesce(out_dir, ''), " +
                    sweep_columns + " FROM runs " + where + " ORDER BY id";
  if (selection.last > 0) sql = "SELECT * FROM (" + sql + " DESC LIMIT ?) ORDER BY id";

  Statement select(db, sql);
  int parameter = 0;
  for (const auto& experiment : selection.experiments) select.bind(++parameter, experiment);
  for (int64_t id : selection.runs) select.bind(++parameter, id);
  for (const auto& sweep : selection.sweeps) select.bind(++parameter, sweep);
  if (selection.last > 0) select.bind(++parameter, static_cast<int64_t>(selection.last));
  std::vector<StoredRun> runs;
  std::vector<std::string> axes_json;
  while (select.step()) {
    StoredRun run;
    run.id = select.column_int(0);
    run.experiment = select.column_text(1);
    try {
      run.status = run_status_from_string(select.column_text(2));
    } catch (const std::invalid_argument& e) {
      throw StoreError(fmt::format("{}: run {}: {}", store.path(), run.id, e.what()));
    }
    run.config = select.column_text(3);
    run.out_dir = select.column_text(4);
    run.sweep_id = select.column_text(5);
    run.job_index = run.sweep_id.empty() ? -1 : static_cast<int>(select.column_int(6));
    axes_json.push_back(select.column_text(7));
    runs.push_back(std::move(run));
  }
  for (size_t i = 0; i < runs.size(); ++i) runs[i].axes = json_object_members(db, axes_json[i]);
  return runs;
}

std::vector<MetricRecord> run_metrics(ResultStore& store, int64_t run_id) {
  Statement select(
      StoreAccess::connection(store),
      fmt::format("SELECT name, value, {} FROM metrics WHERE run_id = ? ORDER BY rowid",
                  kDeclarationColumns));
  select.bind(1, run_id);
  std::vector<MetricRecord> metrics;
  while (select.step()) {
    metrics.push_back({select.column_text(0), select.column_double(1), declaration_at(select, 2)});
  }
  return metrics;
}

std::vector<DecisionCount> run_decision_counts(ResultStore& store, int64_t run_id) {
  Statement select(StoreAccess::connection(store),
                   "SELECT coalesce(expected_action, ''), coalesce(chosen_action, ''), COUNT(*), "
                   "SUM(success) FROM trials WHERE run_id = ? GROUP BY expected_action, "
                   "chosen_action ORDER BY MIN(rowid)");
  select.bind(1, run_id);
  std::vector<DecisionCount> counts;
  while (select.step()) {
    counts.push_back({select.column_text(0), select.column_text(1),
                      static_cast<int>(select.column_int(2)),
                      static_cast<int>(select.column_int(3))});
  }
  return counts;
}

std::vector<TrialRecord> run_trials(ResultStore& store, int64_t run_id) {
  Statement select(StoreAccess::connection(store),
                   "SELECT trial, scenario, coalesce(expected_action, ''), "
                   "coalesce(chosen_action, ''), success, coalesce(failure, ''), "
                   "coalesce(details, '') FROM trials WHERE run_id = ? ORDER BY trial, rowid");
  select.bind(1, run_id);
  std::vector<TrialRecord> trials;
  while (select.step()) {
    trials.push_back({static_cast<int>(select.column_int(0)), select.column_text(1),
                      select.column_text(2), select.column_text(3), select.column_int(4) != 0,
                      select.column_text(5), select.column_text(6)});
  }
  return trials;
}

std::optional<TaskDeclaration> run_task(ResultStore& store, int64_t run_id) {
  return read_task(StoreAccess::connection(store), run_id);
}

}  // namespace corrmp
