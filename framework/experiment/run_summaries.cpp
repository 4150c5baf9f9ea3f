// Recorded runs read back from the result store (run_summaries.hpp).
#include "experiment/run_summaries.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <set>

#include "store/statement.hpp"

namespace corrmp {

namespace {

// "?, ?, ?" for `count` bound parameters.
std::string placeholders(size_t count) {
  std::string text;
  for (size_t i = 0; i < count; ++i) text += i == 0 ? "?" : ", ?";
  return text;
}

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
  std::string where = query.completed_only ? "WHERE status = 'completed'" : "WHERE 1";
  if (!query.experiments.empty()) {
    where += " AND experiment IN (" + placeholders(query.experiments.size()) + ")";
  }
  if (!query.runs.empty()) where += " AND id IN (" + placeholders(query.runs.size()) + ")";
  std::string sql = "SELECT id, experiment, status, config FROM runs " + where + " ORDER BY id";
  if (query.last > 0) sql = "SELECT * FROM (" + sql + " DESC LIMIT ?) ORDER BY id";

  Statement select(store.handle(), sql);
  int parameter = 0;
  for (const auto& experiment : query.experiments) select.bind(++parameter, experiment);
  for (int64_t id : query.runs) select.bind(++parameter, id);
  if (query.last > 0) select.bind(++parameter, static_cast<int64_t>(query.last));
  std::vector<RunSummary> runs;
  while (select.step()) {
    RunSummary run;
    run.id = select.column_int(0);
    run.experiment = select.column_text(1);
    run.status = select.column_text(2);
    run.settings = flatten_yaml(select.column_text(3));
    runs.push_back(std::move(run));
  }

  Statement metrics(store.handle(),
                    "SELECT name, value FROM metrics WHERE run_id = ? ORDER BY rowid");
  Statement trials(store.handle(), "SELECT COUNT(*) FROM trials WHERE run_id = ?");
  for (RunSummary& run : runs) {
    metrics.bind(1, run.id);
    while (metrics.step()) {
      const std::string name = metrics.column_text(0);
      if (!run.metrics.count(name)) run.metric_order.push_back(name);
      run.metrics[name] = metrics.column_double(1);
    }
    metrics.reset();
    trials.bind(1, run.id);
    if (trials.step()) run.trials = static_cast<int>(trials.column_int(0));
    trials.reset();
  }
  return runs;
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
