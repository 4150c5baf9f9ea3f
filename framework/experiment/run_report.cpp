// Reports over recorded runs.
#include "experiment/run_report.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace corrmp {

namespace {

// One prepared statement, finalised on scope exit.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK) {
      throw StoreError(fmt::format("report query failed: {}", sqlite3_errmsg(db)));
    }
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  bool next() { return sqlite3_step(stmt_) == SQLITE_ROW; }
  void bind(int index, int64_t value) { sqlite3_bind_int64(stmt_, index, value); }
  int64_t integer(int column) { return sqlite3_column_int64(stmt_, column); }
  double real(int column) { return sqlite3_column_double(stmt_, column); }
  std::string text(int column) {
    const auto* p = sqlite3_column_text(stmt_, column);
    return p ? reinterpret_cast<const char*>(p) : "";
  }

 private:
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

const double* metric(const RunSummary& run, const std::string& name) {
  const auto it = run.metrics.find(name);
  return it == run.metrics.end() ? nullptr : &it->second;
}

std::string number(const double* value, const char* format = "{:.2f}") {
  return value ? fmt::format(fmt::runtime(format), *value) : "-";
}

std::string success_text(const RunSummary& run) {
  const double* rate = metric(run, "task_success_rate");
  if (!rate) return "-";
  return fmt::format("{} of {}", std::lround(*rate * run.trials), run.trials);
}

std::string percent_text(const double* rate) {
  return rate ? fmt::format("{:.0f}%", 100 * *rate) : "-";
}

std::string pair_text(const RunSummary& run, const std::string& prefix) {
  const double* mean = metric(run, prefix + "_error_mean_cm");
  const double* max = metric(run, prefix + "_error_max_cm");
  if (!mean && !max) return "-";
  return number(mean) + " / " + number(max);
}

std::string varies_text(const RunSummary& run,
                        const std::map<std::string, std::vector<std::string>>& varying) {
  std::string text;
  const auto it = varying.find(run.experiment);
  if (it == varying.end()) return text;
  for (const auto& key : it->second) {
    const auto value = run.settings.find(key);
    text += fmt::format("{}{}={}", text.empty() ? "" : " ", key,
                        value == run.settings.end() ? "(unset)" : value->second);
  }
  return text;
}

// The paper's rows (assets/paper/tables.yaml), as report cells.
struct PaperRow {
  std::string label, success, decision, cor, post;
};

std::vector<PaperRow> paper_rows(const std::string& tables_path) {
  const YAML::Node tables = YAML::LoadFile(tables_path);
  std::vector<PaperRow> rows;
  for (const char* key : {"pc", "ae", "mono"}) {
    const YAML::Node t1 = tables["table_1"][key];
    const YAML::Node t2 = tables["table_2"][key];
    // Decision match per expected correction, weighted by how often each was
    // expected in the paper's draw.
    double matched = 0.0, expected = 0.0;
    for (const auto& entry : t1["decision_match"]) {
      const double count =
          tables["table_1"]["expected"][entry.first.as<std::string>()].as<double>();
      matched += count * entry.second.as<double>();
      expected += count;
    }
    auto pair = [&](const char* name) {
      return fmt::format("{:.2f} / {:.2f}", t2[name][0].as<double>(), t2[name][1].as<double>());
    };
    rows.push_back({fmt::format("paper: {}", key),
                    fmt::format("{} of {}", t1["task_success"].as<int>(), expected),
                    fmt::format("{:.0f}%", 100 * matched / expected), pair("cor_mp"),
                    pair("post_mp")});
  }
  return rows;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
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

std::string report_markdown(const std::vector<RunSummary>& runs, const ReportFormat& format) {
  const auto varying = varying_settings(runs);
  std::string out =
      "| run | experiment | varies | task success | decision match | "
      "cor-MP error mean / max (cm) | post-MP error mean / max (cm) |";
  std::string rule = "|---|---|---|---|---|---|---|";
  for (const auto& name : format.extra_metrics) {
    out += " " + name + " |";
    rule += "---|";
  }
  out += "\n" + rule + "\n";
  for (const auto& run : runs) {
    out += fmt::format("| {} | {} | {} | {} | {} | {} | {} |", run.id, run.experiment,
                       varies_text(run, varying), success_text(run),
                       percent_text(metric(run, "decision_match_rate")), pair_text(run, "cor_mp"),
                       pair_text(run, "post_mp"));
    for (const auto& name : format.extra_metrics) {
      out += " " + number(metric(run, name), "{:.4g}") + " |";
    }
    out += "\n";
  }
  if (!format.paper_tables.empty()) {
    for (const auto& row : paper_rows(format.paper_tables)) {
      out += fmt::format("| | {} | | {} | {} | {} | {} |", row.label, row.success, row.decision,
                         row.cor, row.post);
      for (size_t i = 0; i < format.extra_metrics.size(); ++i) out += " |";
      out += "\n";
    }
  }
  return out;
}

std::string report_csv(const std::vector<RunSummary>& runs, const ReportFormat& format) {
  const auto varying = varying_settings(runs);
  std::vector<std::string> columns{"task_success_rate",     "decision_match_rate",
                                   "cor_mp_error_mean_cm",  "cor_mp_error_max_cm",
                                   "post_mp_error_mean_cm", "post_mp_error_max_cm"};
  columns.insert(columns.end(), format.extra_metrics.begin(), format.extra_metrics.end());
  std::string out = "run,experiment,status,varies,trials";
  for (const auto& c : columns) out += "," + csv_cell(c);
  out += "\n";
  for (const auto& run : runs) {
    out += fmt::format("{},{},{},{},{}", run.id, csv_cell(run.experiment), run.status,
                       csv_cell(varies_text(run, varying)), run.trials);
    for (const auto& c : columns) {
      const double* value = metric(run, c);
      out += "," + (value ? fmt::format("{}", *value) : std::string());
    }
    out += "\n";
  }
  return out;
}

}  // namespace corrmp
