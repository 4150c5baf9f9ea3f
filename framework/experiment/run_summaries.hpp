// Recorded runs read back from the result store for reports: each run's
// status, trial count, metrics and flattened resolved config, and the settings
// that vary between runs of the same experiment (a sweep's parameters).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "store/result_store.hpp"

namespace corrmp {

struct RunSummary {
  int64_t id = 0;
  std::string experiment;
  std::string status;
  int trials = 0;
  std::map<std::string, std::string> settings;  // the resolved config, flattened
  std::map<std::string, double> metrics;
  std::vector<std::string> metric_order;  // the names as the run recorded them
};

struct ReportQuery {
  std::vector<std::string> experiments;  // empty: every experiment
  std::vector<int64_t> runs;             // empty: every run
  int last = 0;                          // > 0: only the newest `last` runs
  bool completed_only = true;
};

// The runs the query selects, oldest first.
std::vector<RunSummary> load_run_summaries(ResultStore& store, const ReportQuery& query);

// A YAML document as dotted key paths to scalar text; lists are one value in
// flow style ("[a, b]"), lists of maps are indexed ("segments.0.name").
std::map<std::string, std::string> flatten_yaml(const std::string& yaml);

// Per experiment, the settings whose value is not the same in all its runs.
std::map<std::string, std::vector<std::string>> varying_settings(
    const std::vector<RunSummary>& runs);

}  // namespace corrmp
