// Test helper: runs recorded in a ResultStore with chosen trials, metrics and
// sweep columns, for the report tests. The sweep columns and table are added
// here when the store's schema does not have them yet.
#pragma once

#include <string>
#include <vector>

#include "report/run_summaries.hpp"
#include "store/result_store.hpp"
#include "store/statement.hpp"

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
  std::string axes;  // JSON object
};

inline void ensure_sweep_schema(ResultStore& store) {
  if (!has_sweep_columns(store)) {
    store.execute(
        "ALTER TABLE runs ADD COLUMN sweep_id TEXT; ALTER TABLE runs ADD COLUMN job_index "
        "INTEGER; ALTER TABLE runs ADD COLUMN axes TEXT;");
  }
  store.execute(
      "CREATE TABLE IF NOT EXISTS sweeps (id TEXT PRIMARY KEY, name TEXT, created_at TEXT, "
      "jobs INTEGER, manifest TEXT)");
}

inline void add_sweep(ResultStore& store, const std::string& id, const std::string& name,
                      int jobs) {
  ensure_sweep_schema(store);
  Statement insert(store.handle(),
                   "INSERT INTO sweeps (id, name, created_at, jobs, manifest) VALUES "
                   "(?, ?, '2026-01-02T03:04:05Z', ?, '{}')");
  insert.bind(1, id).bind(2, name).bind(3, int64_t{jobs}).run();
}

inline int64_t record_run(ResultStore& store, const RunSpec& spec) {
  RunRecord record;
  record.experiment = spec.experiment;
  record.config = spec.config;
  record.config_hash = "hash";
  const int64_t id = store.begin_run(record);
  if (!spec.sweep_id.empty()) {
    ensure_sweep_schema(store);
    Statement update(store.handle(),
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
  store.complete_run(id, trials, spec.metrics);
  return id;
}

// `successes` successful trials of `count`, all expecting and choosing `action`.
inline std::vector<TrialSpec> trials_of(const std::string& action, int count, int successes) {
  std::vector<TrialSpec> trials;
  for (int i = 0; i < count; ++i) trials.push_back({action, action, i < successes});
  return trials;
}

}  // namespace corrmp::testing
