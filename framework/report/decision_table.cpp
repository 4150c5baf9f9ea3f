// Each run's decisions by expected label (decision_table.hpp).
#include "report/decision_table.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "report/report_text.hpp"

namespace corrmp {

namespace {

// The actions chosen for `tally` with their counts: the run's labels in order, then any other.
std::vector<std::pair<std::string, int>> choices(const ActionTally& tally,
                                                 const std::vector<std::string>& labels) {
  std::vector<std::pair<std::string, int>> ordered;
  for (const auto& label : labels) {
    const auto it = tally.chosen.find(label);
    if (it != tally.chosen.end()) ordered.emplace_back(label, it->second);
  }
  for (const auto& [action, count] : tally.chosen) {
    if (std::find(labels.begin(), labels.end(), action) == labels.end()) {
      ordered.emplace_back(action.empty() ? "undecided" : action, count);
    }
  }
  return ordered;
}

std::string choice_text(const ActionTally& tally, const std::vector<std::string>& labels,
                        const char* separator) {
  std::string text;
  for (const auto& [action, count] : choices(tally, labels)) {
    text += fmt::format("{}{} {}", text.empty() ? "" : separator, count, action);
  }
  return text;
}

std::string percent(int part, int whole) {
  return whole > 0 ? fmt::format("{:.0f}%", 100.0 * part / whole) : "-";
}

int matched(const ActionTally& tally, const std::string& label) {
  const auto it = tally.chosen.find(label);
  return it == tally.chosen.end() ? 0 : it->second;
}

bool decides(const RunSummary& run) { return run.metrics.count("decision_match_rate") > 0; }

}  // namespace

std::string decision_markdown(const std::vector<RunSummary>& runs) {
  std::string out =
      "| run | experiment | expected | trials | action choice | decision match | task success |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const auto& run : runs) {
    const std::vector<std::string> labels = decision_labels(run);
    for (const auto& label : labels) {
      const auto tally = run.by_expected.find(label);
      if (tally == run.by_expected.end()) continue;
      const ActionTally& t = tally->second;
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", run.id,
                         markdown_cell(run.experiment), markdown_cell(label), t.trials,
                         markdown_cell(choice_text(t, labels, ", ")),
                         decides(run) ? percent(matched(t, label), t.trials) : "-",
                         percent(t.successes, t.trials));
    }
  }
  return out;
}

std::string decision_csv(const std::vector<RunSummary>& runs) {
  std::string out = "run,experiment,expected,trials,chosen,matched,successes\n";
  for (const auto& run : runs) {
    const std::vector<std::string> labels = decision_labels(run);
    for (const auto& label : labels) {
      const auto tally = run.by_expected.find(label);
      if (tally == run.by_expected.end()) continue;
      const ActionTally& t = tally->second;
      out += fmt::format("{},{},{},{},{},{},{}\n", run.id, csv_cell(run.experiment),
                         csv_cell(label), t.trials, csv_cell(choice_text(t, labels, "; ")),
                         decides(run) ? std::to_string(matched(t, label)) : "", t.successes);
    }
  }
  return out;
}

}  // namespace corrmp
