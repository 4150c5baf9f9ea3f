// Run tables in Markdown and CSV (run_report.hpp).
#include "experiment/run_report.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>

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

// Text inside a Markdown table cell: a '|' would end the cell.
std::string markdown_cell(const std::string& text) {
  std::string escaped;
  for (char c : text) escaped += c == '|' ? std::string("\\|") : std::string(1, c);
  return escaped;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

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
    out += fmt::format("| {} | {} | {} | {} | {} | {} | {} |", run.id,
                       markdown_cell(run.experiment), markdown_cell(varies_text(run, varying)),
                       success_text(run), percent_text(metric(run, "decision_match_rate")),
                       pair_text(run, "cor_mp"), pair_text(run, "post_mp"));
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
