// Recorded runs read back from the result store (run_summaries.hpp).
#include "report/run_summaries.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <set>

#include "store/sweep_queries.hpp"

namespace corrmp {

namespace {

void flatten(const YAML::Node& node, const std::string& path,
             std::map<std::string, std::string>& out) {
  if (node.IsMap()) {
    for (const auto& entry : node) {
      const std::string key = entry.first.as<std::string>();
      flatten(entry.second, path.empty() ? key : path + "." + key, out);
    }
  } else if (node.IsSequence()) {
    const bool of_scalars = std::all_of(node.begin(), node.end(),
                                        [](const YAML::Node& item) { return item.IsScalar(); });
    if (of_scalars) {
      std::string text;
      for (const auto& item : node) text += (text.empty() ? "" : ", ") + item.as<std::string>();
      out[path] = "[" + text + "]";
    } else {
      for (size_t i = 0; i < node.size(); ++i) {
        flatten(node[i], fmt::format("{}.{}", path, i), out);
      }
    }
  } else if (node.IsScalar()) {
    out[path] = node.as<std::string>();
  } else {
    out[path] = "";
  }
}

}  // namespace

std::map<std::string, std::string> flatten_yaml(const std::string& yaml) {
  std::map<std::string, std::string> out;
  flatten(YAML::Load(yaml), "", out);
  return out;
}

std::vector<RunSummary> load_run_summaries(ResultStore& store, const ReportQuery& query) {
  std::vector<RunSummary> runs;
  for (StoredRun& stored : select_runs(store, query)) {
    RunSummary run;
    run.id = stored.id;
    run.experiment = std::move(stored.experiment);
    run.status = stored.status;
    run.settings = flatten_yaml(stored.config);
    run.sweep_id = std::move(stored.sweep_id);
    run.job_index = stored.job_index;
    run.axes = std::move(stored.axes);
    run.out_dir = std::move(stored.out_dir);
    for (MetricRecord& metric : run_metrics(store, run.id)) {
      if (!run.metrics.count(metric.name)) run.metric_order.push_back(metric.name);
      run.metrics[metric.name] = metric.value;
      run.declarations[metric.name] = std::move(metric.declaration);
    }
    for (const DecisionCount& count : run_decision_counts(store, run.id)) {
      if (!run.by_expected.count(count.expected)) run.expected_order.push_back(count.expected);
      ActionTally& tally = run.by_expected[count.expected];
      tally.trials += count.trials;
      tally.successes += count.successes;
      tally.chosen[count.chosen] += count.trials;
      run.trials += count.trials;
      run.successes += count.successes;
    }
    run.task = run_task(store, run.id);
    runs.push_back(std::move(run));
  }
  return runs;
}

bool has_sweep_columns(ResultStore& store) { return records_sweeps(store); }

std::optional<SweepSummary> find_sweep(ResultStore& store, const std::string& id) {
  if (const auto sweep = find_sweep_record(store, id)) {
    return SweepSummary{id, sweep->name, sweep->created_at, sweep->jobs};
  }
  if (!sweep_has_runs(store, id)) return std::nullopt;
  return SweepSummary{id, "", "", 0};
}

MetricDeclaration declared_metric(const std::vector<const RunSummary*>& runs,
                                  const std::string& metric) {
  for (const auto* run : runs) {
    const auto it = run->declarations.find(metric);
    if (it != run->declarations.end()) return it->second;
  }
  return {};
}

MetricDeclaration declared_metric(const std::vector<RunSummary>& runs, const std::string& metric) {
  std::vector<const RunSummary*> pointers;
  for (const auto& run : runs) pointers.push_back(&run);
  return declared_metric(pointers, metric);
}

std::vector<std::string> decision_labels(const RunSummary& run) {
  std::vector<std::string> labels;
  if (run.task) labels = run.task->decision_labels;
  for (const auto& expected : run.expected_order) {
    if (!expected.empty() && std::find(labels.begin(), labels.end(), expected) == labels.end()) {
      labels.push_back(expected);
    }
  }
  return labels;
}

std::optional<std::string> run_setting(const RunSummary& run, const std::string& key) {
  if (key == "experiment") return run.experiment;
  if (const auto axis = run.axes.find(key); axis != run.axes.end()) return axis->second;
  if (const auto setting = run.settings.find(key); setting != run.settings.end()) {
    return setting->second;
  }
  return std::nullopt;
}

bool is_seed_key(const std::string& key) {
  const std::string suffix = ".seed";
  return key == "seed" || (key.size() > suffix.size() &&
                           key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0);
}

std::map<std::string, std::vector<std::string>> varying_settings(
    const std::vector<RunSummary>& runs) {
  std::map<std::string, std::vector<const RunSummary*>> by_experiment;
  for (const auto& run : runs) by_experiment[run.experiment].push_back(&run);
  std::map<std::string, std::vector<std::string>> varying;
  for (const auto& [experiment, group] : by_experiment) {
    std::set<std::string> keys;
    for (const auto* run : group) {
      for (const auto& entry : run->settings) keys.insert(entry.first);
    }
    for (const auto& key : keys) {
      std::set<std::string> values;
      for (const auto* run : group) {
        const auto it = run->settings.find(key);
        values.insert(it == run->settings.end() ? "\x01unset" : it->second);
      }
      if (values.size() > 1) varying[experiment].push_back(key);
    }
  }
  return varying;
}

}  // namespace corrmp
