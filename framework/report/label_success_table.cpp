// Task success per expected label (label_success_table.hpp).
#include "report/label_success_table.hpp"

#include <algorithm>
#include <set>

namespace corrmp {

namespace {

// The labels the runs expected (their expected_<label> metrics), in the order their tasks declared
// them (first seen for runs recorded before tasks were stored), then all trials. The spec's order
// is used only when no run of its experiments declared one.
std::vector<std::string> labels_of(const LabelSuccessSpec& spec, const RunsOf& runs_of) {
  std::vector<std::string> labels;
  bool declared = false;
  for (const auto& experiment : spec.experiments) {
    const auto it = runs_of.find(experiment);
    if (it == runs_of.end()) continue;
    for (const auto* run : it->second) {
      declared = declared || (run->task && !run->task->decision_labels.empty());
      for (const auto& label : decision_labels(*run)) {
        if (!run->metrics.count("expected_" + label)) continue;  // never expected in this run
        if (std::find(labels.begin(), labels.end(), label) == labels.end()) {
          labels.push_back(label);
        }
      }
    }
  }
  if (!declared) {  // runs recorded before tasks were stored: the spec's order, then the rest
    std::vector<std::string> ordered;
    for (const auto& label : spec.labels) {
      if (std::find(labels.begin(), labels.end(), label) != labels.end()) ordered.push_back(label);
    }
    std::vector<std::string> rest;
    for (const auto& label : labels) {
      if (std::find(ordered.begin(), ordered.end(), label) == ordered.end()) rest.push_back(label);
    }
    std::sort(rest.begin(), rest.end());
    ordered.insert(ordered.end(), rest.begin(), rest.end());
    labels = ordered;
  }
  labels.push_back(kAllTrialsRow);
  return labels;
}

}  // namespace

std::string label_success_section(const LabelSuccessSpec& spec, const RunsOf& runs_of,
                                  ReportCells& cells) {
  std::string out = "## " + spec.title + "\n\n" + spec.text +
                    " Each cell: the mean success rate across runs with its 95% interval (over "
                    "the runs expecting the correction at least once), then the trials pooled "
                    "over the runs.\n\n";
  const bool any = std::any_of(spec.experiments.begin(), spec.experiments.end(),
                               [&](const std::string& e) { return runs_of.count(e) > 0; });
  if (!any) return out + spec.absent_text + "\n";
  std::vector<std::string> headings{spec.label_heading};
  headings.insert(headings.end(), spec.experiments.begin(), spec.experiments.end());
  out += markdown_header(headings);
  for (const auto& label : labels_of(spec, runs_of)) {
    std::vector<std::string> row{label};
    for (const auto& experiment : spec.experiments) {
      const auto it = runs_of.find(experiment);
      const auto runs = it == runs_of.end() ? std::vector<const RunSummary*>{} : it->second;
      const std::string metric =
          label == kAllTrialsRow ? "task_success_rate" : "task_success_rate_" + label;
      const ReportCell rate =
          cells.add(metric_cell(spec.table, label, experiment, metric, runs, true, {}, 0.0, true));
      const ReportCell pooled = cells.add(pooled_cell(spec.table, label, experiment, runs));
      row.push_back(rate.runs == 0 ? rate.ours : rate.ours + " · pooled " + pooled.ours);
    }
    out += markdown_row(row);
  }
  return out;
}

}  // namespace corrmp
