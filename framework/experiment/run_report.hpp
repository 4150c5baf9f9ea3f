// Reports over recorded runs: one row per run with the paper's Table I and II
// figures (task success, decision match, cor-MP and post-MP errors) and the
// settings that vary between runs of the same experiment, so a sweep or a
// comparison with the baseline reads as one table (Markdown or CSV).
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

struct ReportFormat {
  std::vector<std::string> extra_metrics;  // more metric columns, by name
  std::string paper_tables;  // when set, the paper's PC, AE and Mono rows from this file
                             // (assets/paper/tables.yaml) are appended (Markdown only)
};

std::string report_markdown(const std::vector<RunSummary>& runs, const ReportFormat& format);
std::string report_csv(const std::vector<RunSummary>& runs, const ReportFormat& format);

}  // namespace corrmp
