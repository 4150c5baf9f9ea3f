// Cells of our runs beside reference numbers (reference_cells.hpp).
#include "report/reference_cells.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "report/metric_ranges.hpp"
#include "report/report_text.hpp"
#include "stats/mean_interval.hpp"
#include "stats/wilson_interval.hpp"

namespace corrmp {

namespace {

std::vector<double> samples(const std::vector<const RunSummary*>& runs, const std::string& metric) {
  std::vector<double> values;
  for (const auto* run : runs) {
    const auto it = run->metrics.find(metric);
    if (it != run->metrics.end()) values.push_back(it->second);
  }
  return values;
}

std::string interval_text(const MeanInterval& m, double low, double high, bool percent,
                          size_t group_runs) {
  if (m.count == 0) return "no runs";
  const double scale = percent ? 100.0 : 1.0;
  const char* unit = percent ? "%" : "";
  const std::string digits = percent ? "{:.1f}" : "{:.2f}";
  const std::string mean = fmt::format(fmt::runtime(digits), scale * m.mean) + unit;
  std::string text = !m.defined() ? mean + " (1 run)"
                                  : fmt::format(fmt::runtime("{} [" + digits + ", " + digits + "]"),
                                                mean, scale * low, scale * high);
  if (m.count > 1 && static_cast<size_t>(m.count) != group_runs) {
    text += fmt::format(" (n={})", m.count);
  }
  return text;
}

std::string printed(const std::string& action, const std::vector<PrintedLabel>& labels) {
  if (action.empty()) return "undecided";
  for (const auto& label : labels) {
    if (label.name == action) return label.printed;
  }
  return action;
}

}  // namespace

ReportCell ReportCells::add(ReportCell cell) {
  cells_.push_back(cell);
  return cell;
}

std::string ReportCells::csv() const {
  std::string out = "table,row,group,quantity,runs,mean,ci_low,ci_high,ours,paper,verdict\n";
  for (const auto& c : cells_) {
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", c.table, csv_cell(c.row),
                       csv_cell(c.group), csv_cell(c.quantity), c.runs, csv_number(c.mean),
                       csv_number(c.low), csv_number(c.high), csv_cell(c.ours), csv_cell(c.paper),
                       csv_cell(c.verdict));
  }
  return out;
}

std::string reproduction_verdict(int runs, double low, double high, double paper,
                                 double paper_rounding, bool higher_is_better) {
  if (runs == 0) return "no runs";
  if (runs == 1 || std::isnan(low) || std::isnan(high)) return "no interval (1 run)";
  if (low > paper + paper_rounding) return higher_is_better ? "better" : "worse";
  if (high < paper - paper_rounding) return higher_is_better ? "worse" : "better";
  return "reproduced";
}

ReportCell metric_cell(const std::string& table, const std::string& row, const std::string& group,
                       const std::string& metric, const std::vector<const RunSummary*>& runs,
                       bool percent, const std::optional<double>& paper, double rounding,
                       bool higher_is_better) {
  const MeanInterval m = mean_interval(samples(runs, metric));
  ReportCell cell{table, row, group, metric, m.count, m.mean, m.low, m.high, "", "", ""};
  const MetricDeclaration declared = declared_metric(runs, metric);
  // The direction the runs declared; the reference's own only when they declared none.
  if (declared.better != Better::neither) higher_is_better = declared.better == Better::higher;
  const IntervalBounds clipped = metric_interval(declared, m);
  cell.low = clipped.low;
  cell.high = clipped.high;
  cell.ours = interval_text(m, cell.low, cell.high, percent, runs.size());
  if (paper) {
    cell.paper = percent ? fmt::format("{:.0f}%", 100 * *paper) : fmt::format("{:.2f}", *paper);
    cell.verdict =
        reproduction_verdict(m.count, cell.low, cell.high, *paper, rounding, higher_is_better);
  } else {
    cell.verdict = "no paper number";
  }
  return cell;
}

ReportCell pooled_cell(const std::string& table, const std::string& row, const std::string& group,
                       const std::vector<const RunSummary*>& runs) {
  int successes = 0, trials = 0;
  for (const auto* run : runs) {
    if (row == kAllTrialsRow) {
      successes += run->successes;
      trials += run->trials;
    } else if (const auto t = run->by_expected.find(row); t != run->by_expected.end()) {
      successes += t->second.successes;
      trials += t->second.trials;
    }
  }
  const ProportionInterval p = wilson_interval(successes, trials);
  ReportCell cell{
      table,  row, group, "task_success_pooled", static_cast<int>(runs.size()), p.rate, p.low,
      p.high, "",  "",    "no paper number"};
  cell.ours = trials == 0 ? "no trials" : fmt::format("{} of {}", successes, trials);
  return cell;
}

ReportCell action_choice_cell(const std::string& table, const std::string& group,
                              const std::string& expected,
                              const std::vector<const RunSummary*>& runs,
                              const std::vector<PrintedLabel>& labels, const std::string& paper) {
  std::map<std::string, int> chosen;
  int with_label = 0;
  for (const auto* run : runs) {
    const auto tally = run->by_expected.find(expected);
    if (tally == run->by_expected.end()) continue;
    ++with_label;
    for (const auto& [action, count] : tally->second.chosen) chosen[action] += count;
  }
  std::vector<std::pair<std::string, int>> ordered(chosen.begin(), chosen.end());
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string text;
  for (const auto& [action, count] : ordered) {
    text += fmt::format("{}{} {}", text.empty() ? "" : ", ", count, printed(action, labels));
  }
  if (with_label == 0) {
    text = runs.empty() ? "no runs" : "never expected";
  } else {
    text += fmt::format(" ({} run{})", with_label, with_label == 1 ? "" : "s");
  }
  return {table, expected, group, "action_choice", with_label, NAN, NAN, NAN, text, paper, ""};
}

std::string markdown_row(const std::vector<std::string>& cells) {
  std::string row = "|";
  for (const auto& cell : cells) row += " " + markdown_cell(cell) + " |";
  return row + "\n";
}

std::string markdown_header(const std::vector<std::string>& headings) {
  std::string rule = "|";
  for (size_t i = 0; i < headings.size(); ++i) rule += "---|";
  return markdown_row(headings) + rule + "\n";
}

}  // namespace corrmp
