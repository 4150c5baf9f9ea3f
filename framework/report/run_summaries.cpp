// Recorded runs read back from the result store (run_summaries.hpp).
#include "report/run_summaries.hpp"

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

bool table_has_column(ResultStore& store, const std::string& table, const std::string& column) {
  Statement info(store.handle(), "SELECT 1 FROM pragma_table_info(?) WHERE name = ?");
  info.bind(1, table).bind(2, column);
  return info.step();
}

bool table_exists(ResultStore& store, const std::string& table) {
  Statement exists(store.handle(), "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?");
  exists.bind(1, table);
  return exists.step();
}

// A JSON object's members as text (strings unquoted), by SQLite's json_each.
std::map<std::string, std::string> json_object_members(ResultStore& store,
                                                       const std::string& json) {
  std::map<std::string, std::string> members;
  if (json.empty()) return members;
  Statement each(store.handle(), "SELECT key, value FROM json_each(?)");
  each.bind(1, json);
  while (each.step()) members[each.column_text(0)] = each.column_text(1);
  return members;
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
  const bool sweeps_recorded = has_sweep_columns(store);
  if (!query.sweeps.empty() && !sweeps_recorded) {
    throw StoreError(
        fmt::format("'{}' records no sweeps (written before runs had a sweep id)", store.path()));
  }
  std::string where = query.completed_only ? "WHERE status = 'completed'" : "WHERE 1";
  if (!query.experiments.empty()) {
    where += " AND experiment IN (" + placeholders(query.experiments.size()) + ")";
  }
  if (!query.runs.empty()) where += " AND id IN (" + placeholders(query.runs.size()) + ")";
  if (!query.sweeps.empty()) {
    where += " AND sweep_id IN (" + placeholders(query.sweeps.size()) + ")";
  }
  const std::string sweep_columns =
      sweeps_recorded ? "sweep_id, job_index, axes" : "NULL, NULL, NULL";
  std::string sql = "SELECT id, experiment, status, config, " + sweep_columns + " FROM runs " +
                    where + " ORDER BY id";
  if (query.last > 0) sql = "SELECT * FROM (" + sql + " DESC LIMIT ?) ORDER BY id";

  Statement select(store.handle(), sql);
  int parameter = 0;
  for (const auto& experiment : query.experiments) select.bind(++parameter, experiment);
  for (int64_t id : query.runs) select.bind(++parameter, id);
  for (const auto& sweep : query.sweeps) select.bind(++parameter, sweep);
  if (query.last > 0) select.bind(++parameter, static_cast<int64_t>(query.last));
  std::vector<RunSummary> runs;
  std::vector<std::string> axes_json;
  while (select.step()) {
    RunSummary run;
    run.id = select.column_int(0);
    run.experiment = select.column_text(1);
    run.status = select.column_text(2);
    run.settings = flatten_yaml(select.column_text(3));
    run.sweep_id = select.column_text(4);
    run.job_index = run.sweep_id.empty() ? -1 : static_cast<int>(select.column_int(5));
    axes_json.push_back(select.column_text(6));
    runs.push_back(std::move(run));
  }
  for (size_t i = 0; i < runs.size(); ++i) runs[i].axes = json_object_members(store, axes_json[i]);

  Statement metrics(store.handle(),
                    "SELECT name, value FROM metrics WHERE run_id = ? ORDER BY rowid");
  Statement trials(store.handle(),
                   "SELECT expected_action, chosen_action, COUNT(*), SUM(success) FROM trials "
                   "WHERE run_id = ? GROUP BY expected_action, chosen_action");
  for (RunSummary& run : runs) {
    metrics.bind(1, run.id);
    while (metrics.step()) {
      const std::string name = metrics.column_text(0);
      if (!run.metrics.count(name)) run.metric_order.push_back(name);
      run.metrics[name] = metrics.column_double(1);
    }
    metrics.reset();
    trials.bind(1, run.id);
    while (trials.step()) {
      const int count = static_cast<int>(trials.column_int(2));
      const int successes = static_cast<int>(trials.column_int(3));
      ActionTally& tally = run.by_expected[trials.column_text(0)];
      tally.trials += count;
      tally.successes += successes;
      tally.chosen[trials.column_text(1)] += count;
      run.trials += count;
      run.successes += successes;
    }
    trials.reset();
  }
  return runs;
}

bool has_sweep_columns(ResultStore& store) {
  return table_has_column(store, "runs", "sweep_id") &&
         table_has_column(store, "runs", "job_index") && table_has_column(store, "runs", "axes");
}

std::optional<SweepSummary> find_sweep(ResultStore& store, const std::string& id) {
  if (table_exists(store, "sweeps")) {
    Statement sweep(store.handle(), "SELECT name, created_at, jobs FROM sweeps WHERE id = ?");
    sweep.bind(1, id);
    if (sweep.step()) {
      return SweepSummary{id, sweep.column_text(0), sweep.column_text(1),
                          static_cast<int>(sweep.column_int(2))};
    }
  }
  if (!has_sweep_columns(store)) return std::nullopt;
  Statement runs(store.handle(), "SELECT 1 FROM runs WHERE sweep_id = ? LIMIT 1");
  runs.bind(1, id);
  if (!runs.step()) return std::nullopt;
  return SweepSummary{id, "", "", 0};
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
