// Reading recorded runs back: the runs a selection picks, and each run's metrics with their
// declarations, its trials, its decisions counted and its task's declaration, as plain records
// (the reports' one way into the database). docs/architecture.md, "Database".
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "store/records.hpp"
#include "store/result_store.hpp"
#include "store/run_status.hpp"

namespace corrmp {

struct RunSelection {
  std::vector<std::string> experiments;  // empty: every experiment
  std::vector<int64_t> runs;             // empty: every run
  std::vector<std::string> sweeps;       // empty: runs of any sweep or none
  int last = 0;                          // > 0: only the newest `last` runs
  bool completed_only = true;
};

struct StoredRun {
  int64_t id = 0;
  std::string experiment;
  RunStatus status = RunStatus::running;
  std::string config;                       // the resolved YAML
  std::string sweep_id;                     // empty outside a sweep
  int job_index = -1;                       // the job within the sweep
  std::map<std::string, std::string> axes;  // the sweep's axis values, as written
  std::string out_dir;                      // "" before the run had a folder
};

// The runs the selection picks, oldest first. Throws StoreError when it selects by sweep in a
// database that records none.
std::vector<StoredRun> select_runs(ResultStore& store, const RunSelection& selection);

// Whether runs carry their sweep (sweep_id, job_index, axes): every database this build opened.
bool records_sweeps(ResultStore& store);

// The run's metrics with their declarations, in the order it recorded them.
std::vector<MetricRecord> run_metrics(ResultStore& store, int64_t run_id);

// The run's trials with one expected and one chosen action: how many, how many succeeded.
struct DecisionCount {
  std::string expected, chosen;
  int trials = 0;
  int successes = 0;
};
// Every pair of expected and chosen action of the run's trials, in the order of the first trial
// of each pair.
std::vector<DecisionCount> run_decision_counts(ResultStore& store, int64_t run_id);

// The run's trials in trial order.
std::vector<TrialRecord> run_trials(ResultStore& store, int64_t run_id);

// What the run's task declared; nothing for a run without an environment or one recorded before
// runs stored their task's declaration (schema 3 and older).
std::optional<TaskDeclaration> run_task(ResultStore& store, int64_t run_id);

}  // namespace corrmp
