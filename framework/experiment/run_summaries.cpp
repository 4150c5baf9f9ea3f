// Recorded runs read back from the result store (run_summaries.hpp).
#include "experiment/run_summaries.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <set>

namespace corrmp {

namespace {

// One prepared statement, finalised on scope exit.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK) {
      throw StoreError(fmt::format("report query failed: {}", sqlite3_errmsg(db)));
    }
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  // True for a row, false when done; any other outcome is an error.
  bool next() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    throw StoreError(fmt::format("report query failed: {}", sqlite3_errmsg(db_)));
  }
  void bind(int index, int64_t value) { sqlite3_bind_int64(stmt_, index, value); }
  int64_t integer(int column) { return sqlite3_column_int64(stmt_, column); }
  double real(int column) { return sqlite3_column_double(stmt_, column); }
  std::string text(int column) {
    const auto* p = sqlite3_column_text(stmt_, column);
    return p ? reinterpret_cast<const char*>(p) : "";
  }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

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
    std::string names;
    for (const auto& e : query.experiments) {
      std::string escaped;
      for (char c : e) escaped += c == '\'' ? std::string("''") : std::string(1, c);
      names += (names.empty() ? "'" : ", '") + escaped + "'";
    }
    where += " AND experiment IN (" + names + ")";
  }
  if (!query.runs.empty()) {
    std::string ids;
    for (int64_t id : query.runs) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
    where += " AND id IN (" + ids + ")";
  }
  std::string sql = "SELECT id, experiment, status, config FROM runs " + where + " ORDER BY id";
  if (query.last > 0) {
    sql = fmt::format("SELECT * FROM ({} DESC LIMIT {}) ORDER BY id", sql, query.last);
  }
  std::vector<RunSummary> runs;
  {
    Statement select(store.handle(), sql);
    while (select.next()) {
      RunSummary run;
      run.id = select.integer(0);
      run.experiment = select.text(1);
      run.status = select.text(2);
      run.settings = flatten_yaml(select.text(3));
      runs.push_back(std::move(run));
    }
  }
  for (RunSummary& run : runs) {
    Statement metrics(store.handle(), "SELECT name, value FROM metrics WHERE run_id = ?");
    metrics.bind(1, run.id);
    while (metrics.next()) run.metrics[metrics.text(0)] = metrics.real(1);
    Statement trials(store.handle(), "SELECT COUNT(*) FROM trials WHERE run_id = ?");
    trials.bind(1, run.id);
    if (trials.next()) run.trials = static_cast<int>(trials.integer(0));
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
