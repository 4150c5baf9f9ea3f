// A reference's decision and error tables beside our runs (decision_tables.hpp).
#include "report/decision_tables.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>
#include <set>

#include "core/config/config_error.hpp"

namespace corrmp {

namespace {

const ConfigNode& child(const ConfigNode& map, const std::string& key) {
  const ConfigNode* found = map.is_map() ? map.find(key) : nullptr;
  return found != nullptr ? *found : map;
}

// Where `key` is written in `map` (the map's place when it is not).
SourceLocation key_where(const ConfigNode& map, const std::string& key) {
  for (const auto& entry : map.entries()) {
    if (entry.key == key) return entry.key_where;
  }
  return map.where();
}

// `values` must hold exactly the keys `names` (the spec's labels or error
// metrics, a `kind`).
template <class T>
void check_keys(const std::map<std::string, T>& values, const std::vector<std::string>& names,
                const std::string& kind, const ConfigNode& node, const std::string& path) {
  for (const auto& name : names) {
    if (!values.count(name)) {
      throw ConfigError(node.where(), path, "no value for the " + kind + " '" + name + "'");
    }
  }
  for (const auto& [key, value] : values) {
    if (std::find(names.begin(), names.end(), key) == names.end()) {
      throw ConfigError(key_where(node, key), path + "." + key,
                        fmt::format("not one of the {}s ({})", kind, fmt::join(names, ", ")));
    }
  }
}

const std::vector<const RunSummary*>& runs_of_column(const RunsOf& runs_of,
                                                     const ReferenceColumn& column) {
  static const std::vector<const RunSummary*> kNone;
  const auto it = runs_of.find(column.experiment);
  return it == runs_of.end() ? kNone : it->second;
}

// The reference's decision match over all trials: its per-label rates
// weighted by how often each label was expected.
double overall_decision_match(const DecisionTablesSpec& spec, const ReferenceColumn& column) {
  double matched = 0.0, expected = 0.0;
  for (const auto& label : spec.labels) {
    const double count = spec.expected.at(label.name);
    matched += count * column.decision_match.at(label.name);
    expected += count;
  }
  return matched / expected;
}

std::string action_choice_table(const DecisionTablesSpec& spec, const RunsOf& runs_of,
                                ReportCells& cells) {
  std::vector<std::string> headings{"Expected correction"};
  for (const auto& column : spec.columns) {
    headings.push_back(column.heading);
    headings.push_back(column.heading + " paper");
  }
  std::string out = markdown_header(headings);
  for (const auto& label : spec.labels) {
    std::vector<std::string> row{label.printed};
    for (const auto& column : spec.columns) {
      const auto paper = column.action_choice.find(label.name);
      const ReportCell cell = cells.add(action_choice_cell(
          spec.decision_table, column.experiment, label.name, runs_of_column(runs_of, column),
          spec.labels, paper == column.action_choice.end() ? "" : paper->second));
      row.push_back(cell.ours);
      row.push_back(cell.paper.empty() ? "-" : cell.paper);
    }
    out += markdown_row(row);
  }
  return out;
}

// Decision match and task success: per label over the runs expecting it at
// least once, and over all trials.
std::string rate_tables(const DecisionTablesSpec& spec, const RunsOf& runs_of, ReportCells& cells) {
  std::vector<std::pair<std::string, std::string>> rows;
  for (const auto& label : spec.labels) rows.push_back({label.name, label.printed});
  rows.push_back(
      {kAllTrialsRow, fmt::format("All ({} trials in the paper)", reference_trials(spec))});
  std::string out;
  for (const auto& [title, prefix] : std::vector<std::pair<std::string, std::string>>{
           {"Decision match", "decision_match_rate"}, {"Task success", "task_success_rate"}}) {
    out += "\n### " + title + "\n\n";
    std::vector<std::string> headings{"Expected correction"};
    for (const auto& column : spec.columns) {
      for (const char* suffix : {"", " paper", " verdict"}) {
        headings.push_back(column.heading + suffix);
      }
    }
    out += markdown_header(headings);
    for (const auto& [label, text] : rows) {
      std::vector<std::string> row{text};
      for (const auto& column : spec.columns) {
        std::optional<double> paper;
        double rounding = spec.rate_rounding;
        const bool decision = prefix == "decision_match_rate";
        if (label != kAllTrialsRow) {
          paper = (decision ? column.decision_match : column.task_success_rate).at(label);
        } else if (decision) {
          paper = overall_decision_match(spec, column);
        } else {  // a count of the reference's trials: exact
          paper = static_cast<double>(column.task_successes) / reference_trials(spec);
          rounding = 0.0;
        }
        const std::string metric = label == kAllTrialsRow ? prefix : prefix + "_" + label;
        const ReportCell cell =
            cells.add(metric_cell(spec.decision_table, label, column.experiment, metric,
                                  runs_of_column(runs_of, column), true, paper, rounding, true));
        row.insert(row.end(), {cell.ours, cell.paper, cell.verdict});
      }
      out += markdown_row(row);
    }
  }
  return out;
}

std::string error_table(const DecisionTablesSpec& spec, const RunsOf& runs_of, ReportCells& cells) {
  std::vector<std::string> metrics, headings{spec.column_kind};
  for (const auto& error : spec.errors) {
    metrics.insert(metrics.end(), {error.mean, error.max});
    for (const char* statistic : {" mean", " max"}) {
      for (const char* suffix : {"", " paper", " verdict"}) {
        headings.push_back(error.heading + statistic + suffix);
      }
    }
  }
  std::string out = markdown_header(headings);
  for (const auto& column : spec.columns) {
    std::vector<std::string> row{column.heading};
    for (const auto& metric : metrics) {
      const ReportCell cell =
          cells.add(metric_cell(spec.error_table, column.heading, column.experiment, metric,
                                runs_of_column(runs_of, column), false, column.errors.at(metric),
                                spec.error_rounding, false));
      row.insert(row.end(), {cell.ours, cell.paper, cell.verdict});
    }
    out += markdown_row(row);
  }
  return out;
}

}  // namespace

void check_decision_tables(const DecisionTablesSpec& spec, const ConfigNode& node,
                           const std::string& path) {
  const std::string prefix = path.empty() ? "" : path + ".";
  std::vector<std::string> labels, error_metrics;
  for (const auto& label : spec.labels) labels.push_back(label.name);
  for (const auto& error : spec.errors)
    error_metrics.insert(error_metrics.end(), {error.mean, error.max});
  check_keys(spec.expected, labels, "label", child(node, "expected"), prefix + "expected");
  const ConfigNode& columns = child(node, "columns");
  auto column_node = columns.items().begin();
  for (size_t i = 0; i < spec.columns.size(); ++i, ++column_node) {
    const ReferenceColumn& column = spec.columns[i];
    const ConfigNode& at = column_node != columns.items().end() ? *column_node : columns;
    const std::string where = prefix + "columns[" + std::to_string(i) + "]";
    for (const auto& [field, values] :
         std::vector<std::pair<std::string, const std::map<std::string, double>*>>{
             {"decision_match", &column.decision_match},
             {"task_success_rate", &column.task_success_rate}}) {
      check_keys(*values, labels, "label", child(at, field), where + "." + field);
    }
    check_keys(column.action_choice, labels, "label", child(at, "action_choice"),
               where + ".action_choice");
    check_keys(column.errors, error_metrics, "error metric", child(at, "errors"),
               where + ".errors");
  }
}

std::vector<std::string> column_experiments(const DecisionTablesSpec& spec) {
  std::vector<std::string> experiments;
  for (const auto& column : spec.columns) experiments.push_back(column.experiment);
  return experiments;
}

int reference_trials(const DecisionTablesSpec& spec) {
  int trials = 0;
  for (const auto& label : spec.labels) trials += spec.expected.at(label.name);
  return trials;
}

std::string decision_tables_section(const DecisionTablesSpec& spec, const RunsOf& runs_of,
                                    ReportCells& cells) {
  const bool any =
      std::any_of(spec.columns.begin(), spec.columns.end(),
                  [&](const ReferenceColumn& c) { return runs_of.count(c.experiment); });
  if (!any) return "## " + spec.absent_title + "\n\n" + spec.absent_text + "\n";
  std::string out = "## " + spec.decision_title +
                    "\n\n### Action choice\n\nThe actions the policy chose in the trials expecting "
                    "each correction, pooled over the runs.\n\n";
  out += action_choice_table(spec, runs_of, cells);
  out += rate_tables(spec, runs_of, cells);
  out += "\n## " + spec.error_title + "\n\n";
  out += error_table(spec, runs_of, cells);

  std::map<std::string, int> verdicts;
  for (const auto& cell : cells.cells()) {
    if (!cell.verdict.empty()) ++verdicts[cell.verdict];
  }
  out += "\nVerdicts over the cells of " + spec.verdicts_of + ":";
  for (const auto& [verdict, count] : verdicts) out += fmt::format(" {} {};", verdict, count);
  out.back() = '.';
  return out + "\n";
}

std::vector<ErrorMetric> reference_columns(const DecisionTablesSpec& spec) {
  std::vector<ErrorMetric> columns;
  for (const auto& error : spec.errors) {
    const std::string unit = error.unit.empty() ? "" : " (" + error.unit + ")";
    columns.push_back({error.mean, error.max, error.heading + " error mean / max" + unit});
  }
  return columns;
}

std::vector<ReferenceRow> reference_rows(const DecisionTablesSpec& spec) {
  std::vector<ReferenceRow> rows;
  std::set<std::string> keys;
  for (const auto& column : spec.columns) {
    if (!keys.insert(column.key).second) continue;
    ReferenceRow row{fmt::format("paper: {}", column.key),
                     fmt::format("{} of {}", column.task_successes, reference_trials(spec)),
                     fmt::format("{:.0f}%", 100 * overall_decision_match(spec, column)),
                     {}};
    for (const auto& error : spec.errors) {
      row.errors[error.mean] =
          fmt::format("{:.2f} / {:.2f}", column.errors.at(error.mean), column.errors.at(error.max));
    }
    rows.push_back(row);
  }
  return rows;
}

bool reference_rows_apply(const std::vector<RunSummary>& runs, const DecisionTablesSpec& spec) {
  return std::any_of(runs.begin(), runs.end(), [&](const RunSummary& run) {
    const auto type = run.settings.find("environment.type");
    return type != run.settings.end() && type->second == spec.environment;
  });
}

}  // namespace corrmp
