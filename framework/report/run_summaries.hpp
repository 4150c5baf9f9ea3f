// Recorded runs read back from the result store for reports: each run's
// status, trials (counted, and tallied per expected action), metrics with their
// declarations, its task's declaration, flattened resolved config and sweep
// axes, and the settings that vary between runs of the same experiment (a
// sweep's parameters). docs/architecture.md, "Database".
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/metric.hpp"
#include "store/records.hpp"
#include "store/result_store.hpp"
#include "store/run_queries.hpp"
#include "store/run_status.hpp"

namespace corrmp {

// A run's trials with one expected action: how many, how many succeeded, and
// how often the policy chose each action (the paper's "action choice").
struct ActionTally {
  int trials = 0;
  int successes = 0;
  std::map<std::string, int> chosen;
};

struct RunSummary {
  int64_t id = 0;
  std::string experiment;
  RunStatus status = RunStatus::completed;
  int trials = 0;
  int successes = 0;                               // trials that succeeded
  std::map<std::string, ActionTally> by_expected;  // by expected action ("" if none)
  std::vector<std::string> expected_order;         // the expected actions, first seen first
  std::string sweep_id;                            // empty outside a sweep
  int job_index = -1;                              // the job within the sweep
  std::map<std::string, std::string> axes;         // the sweep's axis values, as written
  std::map<std::string, std::string> settings;     // the resolved config, flattened
  std::string out_dir;                             // the run's folder as recorded
  std::map<std::string, double> metrics;
  std::vector<std::string> metric_order;                  // the names as the run recorded them
  std::map<std::string, MetricDeclaration> declarations;  // of the metrics, by name
  std::optional<TaskDeclaration> task;  // none without an environment or in an old database
};

using ReportQuery = RunSelection;

// The runs the query selects, oldest first. Databases written before sweeps
// were recorded (no runs.sweep_id) load with empty sweep fields; selecting by
// sweep in one throws StoreError.
std::vector<RunSummary> load_run_summaries(ResultStore& store, const ReportQuery& query);

// Whether runs have the sweep columns (sweep_id, job_index, axes).
bool has_sweep_columns(ResultStore& store);

// The declaration of `metric` by the first of `runs` that recorded it; a metric no run recorded
// is declared with nothing known (unbounded, no unit).
MetricDeclaration declared_metric(const std::vector<RunSummary>& runs, const std::string& metric);
MetricDeclaration declared_metric(const std::vector<const RunSummary*>& runs,
                                  const std::string& metric);

// The decision labels of the run in table order: those its task declared, then any other
// expected action of its trials in the order first seen (all of them, first seen first, for a
// run recorded before runs stored their task's declaration).
std::vector<std::string> decision_labels(const RunSummary& run);

struct SweepSummary {
  std::string id, name, created_at;
  int jobs = 0;  // 0 when the database has no sweeps table
};

// The sweep with this id, from the sweeps table or, without one, from the runs
// that name it; nothing when neither knows it.
std::optional<SweepSummary> find_sweep(ResultStore& store, const std::string& id);

// A setting of the run by key: the sweep axis value as written when the key is
// an axis, else the flattened config's value; "experiment" is the experiment's
// name. Nothing when the run has no such setting.
std::optional<std::string> run_setting(const RunSummary& run, const std::string& key);

// Whether a setting key is a seed (seed, evaluation.seed, ...): seeds are
// the replicates a mean is taken over, never a parameter.
bool is_seed_key(const std::string& key);

// A YAML document as dotted key paths to scalar text; lists are one value in
// flow style ("[a, b]"), lists of maps are indexed ("segments.0.name").
std::map<std::string, std::string> flatten_yaml(const std::string& yaml);

// Per experiment, the settings whose value is not the same in all its runs.
std::map<std::string, std::vector<std::string>> varying_settings(
    const std::vector<RunSummary>& runs);

}  // namespace corrmp
