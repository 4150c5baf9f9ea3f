// Run tables in Markdown and CSV (run_report.hpp).
#include "report/run_report.hpp"

#include <fmt/format.h>

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

}  // namespace

std::string report_markdown(const std::vector<RunSummary>& runs, const ReportFormat& format) {
  const auto varying = varying_settings(runs);
  const std::vector<ReferenceRow>& paper = format.reference_rows;
  std::vector<ErrorMetric> errors = error_metrics(runs);
  for (const auto& column : format.reference_columns) {
    const bool known = std::any_of(errors.begin(), errors.end(),
                                   [&](const ErrorMetric& c) { return c.mean == column.mean; });
    if (!known) errors.push_back(column);
  }
  for (const auto& row : paper) {  // an error only a reference row has, headed by its name
    for (const auto& entry : row.errors) {
      const std::string& mean = entry.first;
      const bool known = std::any_of(errors.begin(), errors.end(),
                                     [&](const ErrorMetric& c) { return c.mean == mean; });
      if (!known) errors.push_back({mean, "", mean});
    }
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
      const auto cell = paper[r].errors.find(column.mean);
      out += " " + (cell == paper[r].errors.end() ? std::string() : cell->second) + " |";
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
