// Trials lost per failure category (failure_share_table.hpp).
#include "report/failure_share_table.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "stats/wilson_interval.hpp"

namespace corrmp {

namespace {

constexpr const char* kTable = "failure_shares";
constexpr const char* kFailed = "failed";
constexpr const char* kOther = "other";

bool declares(const RunSummary& run, const std::string& category) {
  const auto& declared = run.task->failure_categories;
  return std::find(declared.begin(), declared.end(), category) != declared.end();
}

double metric_or_zero(const RunSummary& run, const std::string& name) {
  const auto it = run.metrics.find(name);
  return it == run.metrics.end() ? 0.0 : it->second;
}

// The trials of `runs` lost to `group` (a category, kFailed or kOther) over the trials of the
// runs it applies to; no trials when none declares the category.
struct Lost {
  int lost = 0, trials = 0, runs = 0;
};

Lost lost_to(const std::vector<const RunSummary*>& runs, const std::string& group) {
  Lost out;
  for (const RunSummary* run : runs) {
    const int failed = run->trials - run->successes;
    int lost = 0;
    if (group == kFailed) {
      lost = failed;
    } else if (group == kOther) {
      int categorised = 0;
      for (const auto& category : run->task->failure_categories)
        categorised += static_cast<int>(metric_or_zero(*run, failure_count_metric(category)));
      lost = std::max(0, failed - categorised);
    } else if (declares(*run, group)) {
      lost = static_cast<int>(metric_or_zero(*run, failure_count_metric(group)));
    } else {
      continue;
    }
    out.lost += lost;
    out.trials += run->trials;
    ++out.runs;
  }
  return out;
}

// "12% (3)", "0" when none was lost, "-" when the category is not the experiment's.
std::string share_text(const Lost& l) {
  if (l.runs == 0) return "-";
  if (l.lost == 0) return "0";
  return fmt::format("{:.0f}% ({})", l.trials > 0 ? 100.0 * l.lost / l.trials : 0.0, l.lost);
}

ReportCell share_cell(const std::string& experiment, const std::string& group, const Lost& l) {
  const ProportionInterval p = wilson_interval(l.lost, l.trials);
  return ReportCell{kTable, experiment,    group, "share_of_trials", l.runs, p.rate, p.low,
                    p.high, share_text(l), "",    "no paper number"};
}

}  // namespace

std::string failure_share_section(const RunsOf& runs_of, const std::vector<std::string>& order,
                                  ReportCells& cells) {
  std::string out =
      "## Failures by category\n\n"
      "The share of each experiment's trials (pooled over its runs) that failed, and that "
      "failed for each reason its task declares (the trial's failure starts with the category), "
      "with the count in parentheses; other: failures in no declared category; -: not a "
      "category of the experiment's task.\n\n";
  std::vector<std::pair<std::string, std::vector<const RunSummary*>>> rows;
  std::vector<std::string> categories;
  for (const auto& experiment : order) {
    const auto it = runs_of.find(experiment);
    if (it == runs_of.end()) continue;
    std::vector<const RunSummary*> declared;
    for (const RunSummary* run : it->second) {
      if (!run->task) continue;
      declared.push_back(run);
      for (const auto& category : run->task->failure_categories) {
        if (std::find(categories.begin(), categories.end(), category) == categories.end())
          categories.push_back(category);
      }
    }
    if (!declared.empty()) rows.emplace_back(experiment, declared);
  }
  if (categories.empty()) return out + "No selected run's task declares failure categories.\n";
  std::vector<std::string> headings{"experiment", "runs", "trials", kFailed};
  headings.insert(headings.end(), categories.begin(), categories.end());
  headings.push_back(kOther);
  out += markdown_header(headings);
  for (const auto& [experiment, runs] : rows) {
    int trials = 0;
    for (const RunSummary* run : runs) trials += run->trials;
    std::vector<std::string> row{experiment, std::to_string(runs.size()), std::to_string(trials)};
    std::vector<std::string> groups{kFailed};
    groups.insert(groups.end(), categories.begin(), categories.end());
    groups.push_back(kOther);
    for (const auto& group : groups) {
      const Lost lost = lost_to(runs, group);
      if (lost.runs > 0) cells.add(share_cell(experiment, group, lost));
      row.push_back(share_text(lost));
    }
    out += markdown_row(row);
  }
  return out;
}

}  // namespace corrmp
