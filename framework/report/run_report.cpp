// Run tables in Markdown and CSV (run_report.hpp).
#include "report/run_report.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>

#include "report/error_metrics.hpp"
#include "report/report_text.hpp"

namespace corrmp {

namespace {

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

std::string error_number(const double* value) { return value ? fixed_number(*value, 2) : "-"; }

std::string pair_text(const RunSummary& run, const ErrorMetric& column) {
  const double* mean = metric(run, column.mean);
  const double* max = metric(run, column.max);
  if (!mean && !max) return "-";
  return error_number(mean) + " / " + error_number(max);
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
  std::string label, success, decision;
  std::map<std::string, std::string> errors;  // by the paper's error key (<segment>_mp)
};

std::vector<PaperRow> paper_rows(const std::string& tables_path) {
  const YAML::Node tables = YAML::LoadFile(tables_path);
  std::vector<PaperRow> rows;
  for (const auto& group : tables["table_1"]) {  // the paper's columns, in its order
    const std::string key = group.first.as<std::string>();
    if (key == "expected") continue;
    const YAML::Node t1 = group.second;
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
    PaperRow row{fmt::format("paper: {}", key),
                 fmt::format("{} of {}", t1["task_success"].as<int>(), expected),
                 fmt::format("{:.0f}%", 100 * matched / expected),
                 {}};
    for (const auto& entry : t2) {  // cor_mp: [mean, max] in the task's error unit
      row.errors[entry.first.as<std::string>()] = fmt::format(
          "{:.2f} / {:.2f}", entry.second[0].as<double>(), entry.second[1].as<double>());
    }
    rows.push_back(row);
  }
  return rows;
}

// The unit the runs' errors are in: the one their task declared, or for runs recorded before
// tasks were stored, the one their error metrics declared.
std::string error_unit(const std::vector<RunSummary>& runs) {
  for (const auto& run : runs) {
    if (run.task && !run.task->error_unit.empty()) return run.task->error_unit;
  }
  for (const auto& run : runs) {
    for (const auto& error : error_metrics({run})) {
      const std::string& unit = run.declarations.at(error.mean).unit;
      if (!unit.empty()) return unit;
    }
  }
  return "";
}

// The mean metric of the error column of the paper's error `key` (<segment>_mp, the stem of the
// task's <segment>_mp_error_mean_<unit>) among `errors`, the column added when no run recorded it.
std::string paper_error_column(std::vector<ErrorMetric>& errors, const std::string& key,
                               const std::string& unit) {
  const std::string mean = key + "_error_mean_" + unit;
  const auto known = std::find_if(errors.begin(), errors.end(),
                                  [&](const ErrorMetric& column) { return column.mean == mean; });
  if (known == errors.end()) {
    errors.push_back({mean, key + "_error_max_" + unit,
                      fmt::format("paper's {} error mean / max ({})", key, unit)});
  }
  return mean;
}

}  // namespace

std::string paper_environment(const std::string& paper_tables) {
  const YAML::Node environment = YAML::LoadFile(paper_tables)["environment"];
  return environment ? environment.as<std::string>() : "";
}

bool paper_rows_apply(const std::vector<RunSummary>& runs, const std::string& paper_tables) {
  const std::string environment = paper_environment(paper_tables);
  if (environment.empty()) return true;  // tables that name no task go with any runs
  return std::any_of(runs.begin(), runs.end(), [&](const RunSummary& run) {
    const auto type = run.settings.find("environment.type");
    return type != run.settings.end() && type->second == environment;
  });
}

std::string report_markdown(const std::vector<RunSummary>& runs, const ReportFormat& format) {
  const auto varying = varying_settings(runs);
  std::vector<PaperRow> paper;
  if (!format.paper_tables.empty() && paper_rows_apply(runs, format.paper_tables))
    paper = paper_rows(format.paper_tables);
  std::vector<ErrorMetric> errors = error_metrics(runs);
  const std::string unit = paper.empty() ? "" : error_unit(runs);
  std::vector<std::map<std::string, std::string>> paper_errors;  // by error column's mean
  for (const auto& row : paper) {  // the paper's errors get their columns too
    std::map<std::string, std::string> cells;
    for (const auto& [key, text] : row.errors) {
      cells[paper_error_column(errors, key, unit)] = text;
    }
    paper_errors.push_back(cells);
  }
  std::string out = "| run | experiment |";
  std::string rule = "|---|---|";
  if (format.status_column) {
    out += " status |";
    rule += "---|";
  }
  out += " varies | task success | decision match |";
  rule += "---|---|---|";
  for (const auto& column : errors) {
    out += " " + column.heading + " |";
    rule += "---|";
  }
  for (const auto& name : format.extra_metrics) {
    out += " " + name + " |";
    rule += "---|";
  }
  out += "\n" + rule + "\n";
  for (const auto& run : runs) {
    out += fmt::format("| {} | {} |", run.id, markdown_cell(run.experiment));
    if (format.status_column) out += " " + markdown_cell(to_string(run.status)) + " |";
    out += fmt::format(" {} | {} | {} |", markdown_cell(varies_text(run, varying)),
                       success_text(run), percent_text(metric(run, "decision_match_rate")));
    for (const auto& column : errors) out += " " + pair_text(run, column) + " |";
    for (const auto& name : format.extra_metrics) {
      out += " " + number(metric(run, name), "{:.4g}") + " |";
    }
    out += "\n";
  }
  for (size_t r = 0; r < paper.size(); ++r) {
    out += fmt::format("| | {} |{} | {} | {} |", paper[r].label, format.status_column ? " |" : "",
                       paper[r].success, paper[r].decision);
    for (const auto& column : errors) {
      const auto cell = paper_errors[r].find(column.mean);
      out += " " + (cell == paper_errors[r].end() ? std::string() : cell->second) + " |";
    }
    for (size_t i = 0; i < format.extra_metrics.size(); ++i) out += " |";
    out += "\n";
  }
  return out;
}

std::string report_csv(const std::vector<RunSummary>& runs, const ReportFormat& format) {
  const auto varying = varying_settings(runs);
  std::vector<std::string> columns{"task_success_rate", "decision_match_rate"};
  for (const auto& column : error_metrics(runs)) {
    columns.push_back(column.mean);
    columns.push_back(column.max);
  }
  columns.insert(columns.end(), format.extra_metrics.begin(), format.extra_metrics.end());
  std::string out = "run,experiment,status,varies,trials";
  for (const auto& c : columns) out += "," + csv_cell(c);
  out += "\n";
  for (const auto& run : runs) {
    out += fmt::format("{},{},{},{},{}", run.id, csv_cell(run.experiment), to_string(run.status),
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
