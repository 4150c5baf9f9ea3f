// The reproduction report (reproduction_report.hpp).
#include "report/reproduction_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "report/failure_share_table.hpp"

namespace corrmp {

namespace {

// Fewer seeds of an experiment than this make the report warn that its verdicts say little.
constexpr size_t kMinimumSeeds = 3;

std::string runs_section(const RunsOf& runs_of, const std::vector<std::string>& experiments,
                         const std::vector<RunSummary>& all_runs) {
  std::string out = markdown_header({"experiment", "runs", "seeds", "trials", "run ids"});
  for (const auto& experiment : experiments) {
    const auto it = runs_of.find(experiment);
    if (it == runs_of.end()) {
      out += markdown_row({experiment, "0", "-", "-", "-"});
      continue;
    }
    std::string seeds, ids;
    int trials = 0;
    for (const auto* run : it->second) {
      const auto seed = run_setting(*run, "seed");
      seeds += (seeds.empty() ? "" : ", ") + (seed ? *seed : std::string("?"));
      ids += (ids.empty() ? "" : ", ") + std::to_string(run->id);
      trials += run->trials;
    }
    out += markdown_row(
        {experiment, std::to_string(it->second.size()), seeds, std::to_string(trials), ids});
  }
  std::map<std::string, int> others;
  for (const auto& run : all_runs) {
    if (std::find(experiments.begin(), experiments.end(), run.experiment) == experiments.end()) {
      ++others[run.experiment];
    }
  }
  if (!others.empty()) {
    out += "\nOther experiments in the selection, not in the paper's tables:";
    for (const auto& [experiment, count] : others)
      out += fmt::format(" {} ({});", experiment, count);
    out.back() = '.';
    out += "\n";
  }
  return out;
}

// A warning above the tables when the runs are too small for their verdicts to say much: fewer
// trials in a run than the reference's, or fewer than kMinimumSeeds training seeds of an
// experiment (the reproduction runs 5). "" when they are not.
std::string scale_note(const RunsOf& runs_of, int paper_trials) {
  int fewest_trials = paper_trials;
  size_t fewest_seeds = kMinimumSeeds;
  for (const auto& [experiment, runs] : runs_of) {
    std::set<std::string> seeds;
    for (const RunSummary* run : runs) {
      fewest_trials = std::min(fewest_trials, run->trials);
      const auto seed = run->settings.find("seed");
      seeds.insert(seed == run->settings.end() ? std::to_string(run->id) : seed->second);
    }
    fewest_seeds = std::min(fewest_seeds, seeds.size());
  }
  std::vector<std::string> reasons;
  if (fewest_trials < paper_trials)
    reasons.push_back(
        fmt::format("as few as {} trials in a run (the paper: {})", fewest_trials, paper_trials));
  if (fewest_seeds < kMinimumSeeds)
    reasons.push_back(fmt::format("{} training seed{} of an experiment (the reproduction: 5)",
                                  fewest_seeds, fewest_seeds == 1 ? "" : "s"));
  if (reasons.empty()) return "";
  return fmt::format(
      "**Small runs.** The selection has {}. The intervals are wide, so \"reproduced\" only "
      "says that the paper's number is not ruled out: such runs check that the pipeline works "
      "(as `scripts/reproduce_paper --quick` does), not what the method achieves.\n\n",
      fmt::join(reasons, " and "));
}

}  // namespace

std::vector<std::string> reproduction_experiments(const ReproductionSpec& spec) {
  std::vector<std::string> experiments = column_experiments(spec.decision_tables);
  const auto& others = spec.label_success.experiments;
  experiments.insert(experiments.end(), others.begin(), others.end());
  return experiments;
}

std::string figures_section(const std::vector<ReportFigure>& figures,
                            const std::vector<std::string>& notes) {
  std::string out = "## Figures\n\n";
  if (figures.empty()) out += "No figures listed.\n";
  for (size_t i = 0; i < figures.size(); ++i) {
    out += fmt::format("![Figure {}: {}]({})\n\n*Figure {}: {}*\n\n", i + 1, figures[i].caption,
                       figures[i].path, i + 1, figures[i].caption);
  }
  if (!notes.empty()) {
    out += figures.empty() ? "\nSkipped:\n\n" : "Skipped:\n\n";
    for (const auto& note : notes) out += "- " + note + "\n";
  }
  return out;
}

ReproductionReport reproduction_report(const ReproductionSpec& spec,
                                       const ReproductionInputs& inputs) {
  const std::vector<std::string> experiments = reproduction_experiments(spec);
  RunsOf runs_of;
  for (const auto& run : inputs.runs) {
    if (std::find(experiments.begin(), experiments.end(), run.experiment) != experiments.end()) {
      runs_of[run.experiment].push_back(&run);
    }
  }
  if (runs_of.empty()) {
    throw ReproductionError(
        fmt::format("the selected runs hold none of the paper's experiments ({})",
                    fmt::join(experiments, ", ")));
  }

  std::string md = "# " + spec.title + "\n\n";
  if (inputs.sweep) {
    const SweepSummary& s = *inputs.sweep;
    md += fmt::format("Sweep `{}`", s.id);
    if (!s.name.empty())
      md += fmt::format(" ({}, created {}, {} jobs)", s.name, s.created_at, s.jobs);
    md += fmt::format(": {} runs read.\n\n", inputs.runs.size());
  }
  md += scale_note(runs_of, reference_trials(spec.decision_tables));
  md += "## Runs\n\n" + runs_section(runs_of, experiments, inputs.runs);
  md +=
      "\n## How to read the tables\n\n"
      "Each of our cells is the mean across the runs (seeds) with its 95% confidence interval "
      "[low, high] (Student t, n - 1 degrees of freedom; intervals clipped to the values a metric "
      "can take: errors at 0, rates to [0, 100]%). "
      "With one run there is no interval. A rate per expected correction is averaged over the "
      "runs that expected that correction at least once; (n=k) marks fewer runs than the "
      "group has. The paper's number is beside each cell (" +
      spec.reference_source +
      "). Verdict: "
      "reproduced when the paper's number, within half its last printed digit, lies inside our "
      "interval; better or worse when the interval lies entirely on that side (higher is "
      "better for rates, lower for errors).\n\n";
  ReportCells cells;
  md += decision_tables_section(spec.decision_tables, runs_of, cells);
  md += "\n" + label_success_section(spec.label_success, runs_of, cells);
  // Every selected experiment's failures: the paper's, then the others in the selection.
  RunsOf all_runs = runs_of;
  std::vector<std::string> order = experiments;
  for (const auto& run : inputs.runs) {
    if (!runs_of.count(run.experiment)) all_runs[run.experiment].push_back(&run);
  }
  for (const auto& [experiment, runs] : all_runs) {
    if (!runs_of.count(experiment)) order.push_back(experiment);
  }
  md += "\n" + failure_share_section(all_runs, order, cells);
  md += "\n" + figures_section(inputs.figures, inputs.figure_notes);
  return {md, cells.csv()};
}

void write_reproduction_report(const ReproductionReport& report, const std::string& directory) {
  std::filesystem::create_directories(directory);
  for (const auto& [name, text] :
       {std::pair<std::string, const std::string&>{"report.md", report.markdown},
        {"report.csv", report.csv}}) {
    const std::string path = (std::filesystem::path(directory) / name).string();
    std::ofstream file(path);
    file << text;
    if (!file) throw std::runtime_error("cannot write '" + path + "'");
  }
}

}  // namespace corrmp
