// Test helper: runs recorded in a ResultStore with chosen trials, metrics and
// sweep columns, for the report tests. The sweep columns and table are added
// here when the store's schema does not have them yet. A metric given without a
// declaration gets the one a migration gives it (as_migrated).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/run_summaries.hpp"
#include "store/legacy_metrics.hpp"
#include "store/result_store.hpp"
#include "store/statement.hpp"
#include "support/store_sql.hpp"

namespace corrmp::testing {

struct TrialSpec {
  std::string expected, chosen;
  bool success = false;
};

struct RunSpec {
  std::string experiment;
  std::string config = "seed: 0\n";
  std::vector<TrialSpec> trials;
  std::vector<MetricRecord> metrics;
  std::string sweep_id;  // empty: outside a sweep
  int job_index = 0;
  std::string axes;                     // JSON object
  std::optional<TaskDeclaration> task;  // what the run's task declared
};

// The metrics, each given without a declaration declared as a migration of a database written
// before metrics were declared declares it (store/legacy_metrics.hpp): what the tests' names
// (task_success_rate, cor_mp_error_mean_cm, ...) are declared as by the code that records them.
inline std::vector<MetricRecord> as_migrated(std::vector<MetricRecord> metrics) {
  for (auto& metric : metrics) {
    if (metric.declaration == MetricDeclaration{}) {
      metric.declaration = inferred_declaration(metric.name);
    }
  }
  return metrics;
}

// A run summary made by hand, each of its metrics without a declaration declared as above.
inline void declare_as_migrated(RunSummary& run) {
  for (const auto& entry : run.metrics) {
    if (!run.declarations.count(entry.first)) {
      run.declarations[entry.first] = inferred_declaration(entry.first);
    }
  }
}

inline void ensure_sweep_schema(ResultStore& store) {
  if (!has_sweep_columns(store)) {
    testing::execute_sql(
        store,
        "ALTER TABLE runs ADD COLUMN sweep_id TEXT; ALTER TABLE runs ADD COLUMN job_index "
        "INTEGER; ALTER TABLE runs ADD COLUMN axes TEXT;");
  }
  testing::execute_sql(
      store,
      "CREATE TABLE IF NOT EXISTS sweeps (id TEXT PRIMARY KEY, name TEXT, created_at TEXT, "
      "jobs INTEGER, manifest TEXT)");
}

inline void add_sweep(ResultStore& store, const std::string& id, const std::string& name,
                      int jobs) {
  ensure_sweep_schema(store);
  Statement insert(StoreAccess::connection(store),
                   "INSERT INTO sweeps (id, name, created_at, jobs, manifest) VALUES "
                   "(?, ?, '2026-01-02T03:04:05Z', ?, '{}')");
  insert.bind(1, id).bind(2, name).bind(3, int64_t{jobs}).run();
}

inline int64_t record_run(ResultStore& store, const RunSpec& spec) {
  RunRecord record;
  record.experiment = spec.experiment;
  record.config = spec.config;
  record.config_hash = "hash";
  record.task = spec.task;
  const int64_t id = store.begin_run(record);
  if (!spec.sweep_id.empty()) {
    ensure_sweep_schema(store);
    Statement update(StoreAccess::connection(store),
                     "UPDATE runs SET sweep_id = ?, job_index = ?, axes = ? WHERE id = ?");
    update.bind(1, spec.sweep_id).bind(2, int64_t{spec.job_index}).bind(3, spec.axes).bind(4, id);
    update.run();
  }
  std::vector<TrialRecord> trials;
  for (const auto& t : spec.trials) {
    TrialRecord trial;
    trial.trial = static_cast<int>(trials.size());
    trial.scenario = "{}";
    trial.expected_action = t.expected;
    trial.chosen_action = t.chosen;
    trial.success = t.success;
    trial.failure = t.success ? "" : "missed";
    trials.push_back(trial);
  }
  store.complete_run(id, trials, as_migrated(spec.metrics));
  return id;
}

// `successes` successful trials of `count`, all expecting and choosing `action`.
inline std::vector<TrialSpec> trials_of(const std::string& action, int count, int successes) {
  std::vector<TrialSpec> trials;
  for (int i = 0; i < count; ++i) trials.push_back({action, action, i < successes});
  return trials;
}

// A completed run of four trials (expected and chosen push) with the given task success, a
// decision match of 75%, a cor-MP error of `cor_error` cm (its max twice that) and 100 training
// demonstrations.
inline int64_t record_scored_run(ResultStore& store, const std::string& experiment,
                                 const std::string& config, double success, double cor_error) {
  const int64_t id = store.begin_run({experiment, config, "hash", 0, "", false, "", "", 0, ""});
  std::vector<TrialRecord> trials;
  for (int t = 0; t < 4; ++t) trials.push_back({t, "{}", "push", "push", t < 4 * success, "", ""});
  store.complete_run(id, trials,
                     as_migrated({{"task_success_rate", success},
                                  {"decision_match_rate", 0.75},
                                  {"cor_mp_error_mean_cm", cor_error},
                                  {"cor_mp_error_max_cm", 2 * cor_error},
                                  {"demonstrations_train", 100}}));
  return id;
}

}  // namespace corrmp::testing
