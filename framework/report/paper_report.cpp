// The paper-reproduction report (paper_report.hpp).
#include "report/paper_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <tuple>

#include "report/metric_ranges.hpp"
#include "report/report_text.hpp"
#include "stats/mean_interval.hpp"
#include "stats/wilson_interval.hpp"

namespace corrmp {

namespace {

// The corridor experiments as the paper's Tables I and II name them.
struct CorridorGroup {
  std::string experiment, paper_key, label;
};
const std::vector<CorridorGroup> kCorridorGroups = {
    {"corridor_pc", "pc", "PC"}, {"corridor_ae", "ae", "AE"}, {"corridor_mono", "mono", "Mono"}};
// Table I's rows: the expected corrections, as the paper prints them.
const std::vector<std::pair<std::string, std::string>> kCorridorLabels = {
    {"push", "Push"}, {"none", "No Correction"}, {"pull", "Pull"}};
const std::vector<std::string> kRopeExperiments = {"rope_color", "rope_perfect",
                                                   "rope_nocorrection", "rope_mono"};
// The rope's correction types in the order the rope task names them.
const std::vector<std::string> kRopeLabelOrder = {
    "none", "posterior-to-anterior", "anterior-to-posterior", "lateral", "vertical", "combined"};
const std::string kAllRow = "all";
// The paper prints rates as whole percents and errors to 0.01 cm: its value
// stands for anything within half that digit.
constexpr double kPercentRounding = 0.005;
constexpr double kCentimetreRounding = 0.005;

using RunsOf = std::map<std::string, std::vector<const RunSummary*>>;

// Fewer seeds of an experiment than this make the report warn that its verdicts say little.
constexpr size_t kMinimumSeeds = 3;

std::vector<double> samples(const std::vector<const RunSummary*>& runs, const std::string& metric) {
  std::vector<double> values;
  for (const auto* run : runs) {
    const auto it = run->metrics.find(metric);
    if (it != run->metrics.end()) values.push_back(it->second);
  }
  return values;
}

// One of our numbers beside the paper's: a row of report.csv and a cell (with
// its paper value and verdict) of report.md.
struct Cell {
  std::string table, row, group, quantity;
  int runs = 0;
  double mean = NAN, low = NAN, high = NAN;
  std::string ours, paper, verdict;
};

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

// A cell of a metric across runs; its interval is clipped to the values the
// metric can take (its declared range: errors at 0, rates to [0, 1]). Without
// a paper value the verdict says so.
Cell metric_cell(const std::string& table, const std::string& row, const std::string& group,
                 const std::string& metric, const std::vector<const RunSummary*>& runs,
                 bool percent, const std::optional<double>& paper, double rounding,
                 bool higher_is_better) {
  const MeanInterval m = mean_interval(samples(runs, metric));
  Cell cell{table, row, group, metric, m.count, m.mean, m.low, m.high, "", "", ""};
  const IntervalBounds clipped = metric_interval(declared_metric(runs, metric), m);
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

std::string action_text(const std::string& action) {
  if (action.empty()) return "undecided";
  for (const auto& [label, text] : kCorridorLabels) {
    if (label == action) return text;
  }
  return action;
}

// Table I's action choice: the chosen actions of the trials expecting
// `expected`, pooled over the runs.
Cell action_choice_cell(const std::string& group, const std::string& expected,
                        const std::vector<const RunSummary*>& runs, const std::string& paper) {
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
    text += fmt::format("{}{} {}", text.empty() ? "" : ", ", count, action_text(action));
  }
  if (with_label == 0) {
    text = runs.empty() ? "no runs" : "never expected";
  } else {
    text += fmt::format(" ({} run{})", with_label, with_label == 1 ? "" : "s");
  }
  return {"table_1", expected, group, "action_choice", with_label, NAN, NAN, NAN, text, paper, ""};
}

// The pooled success of trials (of one expected correction, or all) with a
// Wilson interval.
Cell pooled_cell(const std::string& table, const std::string& row, const std::string& group,
                 const std::vector<const RunSummary*>& runs) {
  int successes = 0, trials = 0;
  for (const auto* run : runs) {
    if (row == kAllRow) {
      successes += run->successes;
      trials += run->trials;
    } else if (const auto t = run->by_expected.find(row); t != run->by_expected.end()) {
      successes += t->second.successes;
      trials += t->second.trials;
    }
  }
  const ProportionInterval p = wilson_interval(successes, trials);
  Cell cell{table,  row, group, "task_success_pooled", static_cast<int>(runs.size()), p.rate, p.low,
            p.high, "",  "",    "no paper number"};
  cell.ours = trials == 0 ? "no trials" : fmt::format("{} of {}", successes, trials);
  return cell;
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

class CellTable {
 public:
  // Records the cell and returns a copy (a reference would not outlive the
  // next add).
  Cell add(Cell cell) {
    cells_.push_back(cell);
    return cell;
  }
  const std::vector<Cell>& cells() const { return cells_; }

 private:
  std::vector<Cell> cells_;
};

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
    out += "\nOther experiments in the selection, not in this report:";
    for (const auto& [experiment, count] : others)
      out += fmt::format(" {} ({});", experiment, count);
    out.back() = '.';
    out += "\n";
  }
  return out;
}

// The paper's decision match over all trials: its per-correction rates
// weighted by how often each correction was expected.
double paper_overall_decision_match(const YAML::Node& tables, const std::string& key) {
  double matched = 0.0, expected = 0.0;
  for (const auto& [label, text] : kCorridorLabels) {
    const double count = tables["table_1"]["expected"][label].as<double>();
    matched += count * tables["table_1"][key]["decision_match"][label].as<double>();
    expected += count;
  }
  return matched / expected;
}

double paper_expected_trials(const YAML::Node& tables) {
  double expected = 0.0;
  for (const auto& [label, text] : kCorridorLabels) {
    expected += tables["table_1"]["expected"][label].as<double>();
  }
  return expected;
}

std::string corridor_sections(const RunsOf& runs_of, const YAML::Node& tables, CellTable& cells) {
  auto runs = [&](const CorridorGroup& g) {
    const auto it = runs_of.find(g.experiment);
    return it == runs_of.end() ? std::vector<const RunSummary*>{} : it->second;
  };
  std::vector<std::pair<std::string, std::string>> rows = kCorridorLabels;
  rows.push_back(
      {kAllRow, fmt::format("All ({:.0f} trials in the paper)", paper_expected_trials(tables))});
  std::string out =
      "## Table I: action choice, decision match and task success (push through the "
      "corridor)\n\n### Action choice\n\nThe actions the policy chose in the trials expecting "
      "each correction, pooled over the runs.\n\n";
  {
    std::vector<std::string> headings{"Expected correction"};
    for (const auto& g : kCorridorGroups) {
      headings.push_back(g.label);
      headings.push_back(g.label + " paper");
    }
    out += markdown_header(headings);
    for (const auto& [label, text] : kCorridorLabels) {
      std::vector<std::string> row{text};
      for (const auto& g : kCorridorGroups) {
        const YAML::Node paper = tables["table_1_action_choice"][g.paper_key][label];
        const Cell cell = cells.add(
            action_choice_cell(g.experiment, label, runs(g), paper ? paper.as<std::string>() : ""));
        row.push_back(cell.ours);
        row.push_back(cell.paper.empty() ? "-" : cell.paper);
      }
      out += markdown_row(row);
    }
  }
  // Decision match and task success: per correction over the runs expecting
  // it at least once, and over all trials.
  for (const auto& [title, prefix, paper_field] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"Decision match", "decision_match_rate", "decision_match"},
           {"Task success", "task_success_rate", "task_success_rate"}}) {
    out += "\n### " + title + "\n\n";
    std::vector<std::string> headings{"Expected correction"};
    for (const auto& g : kCorridorGroups) {
      for (const char* suffix : {"", " paper", " verdict"}) headings.push_back(g.label + suffix);
    }
    out += markdown_header(headings);
    for (const auto& [label, text] : rows) {
      std::vector<std::string> row{text};
      for (const auto& g : kCorridorGroups) {
        std::optional<double> paper;
        double rounding = kPercentRounding;
        if (label != kAllRow) {
          paper = tables["table_1"][g.paper_key][paper_field][label].as<double>();
        } else if (prefix == "decision_match_rate") {
          paper = paper_overall_decision_match(tables, g.paper_key);
        } else {  // a count of the paper's trials: exact
          paper = tables["table_1"][g.paper_key]["task_success"].as<double>() /
                  paper_expected_trials(tables);
          rounding = 0.0;
        }
        const std::string metric = label == kAllRow ? prefix : prefix + "_" + label;
        const Cell cell = cells.add(metric_cell("table_1", label, g.experiment, metric, runs(g),
                                                true, paper, rounding, true));
        row.insert(row.end(), {cell.ours, cell.paper, cell.verdict});
      }
      out += markdown_row(row);
    }
  }

  out += "\n## Table II: prediction errors of the MP trajectories (cm)\n\n";
  const std::vector<std::tuple<std::string, std::string, int>> errors{
      {"cor_mp_error_mean_cm", "cor_mp", 0},
      {"cor_mp_error_max_cm", "cor_mp", 1},
      {"post_mp_error_mean_cm", "post_mp", 0},
      {"post_mp_error_max_cm", "post_mp", 1}};
  std::vector<std::string> headings{"Network"};
  for (const char* column : {"cor-MP mean", "cor-MP max", "post-MP mean", "post-MP max"}) {
    for (const char* suffix : {"", " paper", " verdict"}) {
      headings.push_back(std::string(column) + suffix);
    }
  }
  out += markdown_header(headings);
  for (const auto& g : kCorridorGroups) {
    std::vector<std::string> row{g.label};
    for (const auto& [metric, segment, index] : errors) {
      const YAML::Node paper = tables["table_2"][g.paper_key][segment][index];
      const Cell cell =
          cells.add(metric_cell("table_2", g.label, g.experiment, metric, runs(g), false,
                                paper.as<double>(), kCentimetreRounding, false));
      row.insert(row.end(), {cell.ours, cell.paper, cell.verdict});
    }
    out += markdown_row(row);
  }

  std::map<std::string, int> verdicts;
  for (const auto& cell : cells.cells()) {
    if (!cell.verdict.empty()) ++verdicts[cell.verdict];
  }
  out += "\nVerdicts over the cells of Tables I and II:";
  for (const auto& [verdict, count] : verdicts) out += fmt::format(" {} {};", verdict, count);
  out.back() = '.';
  return out + "\n";
}

std::vector<std::string> rope_labels(const RunsOf& runs_of) {
  std::set<std::string> found;
  for (const auto& experiment : kRopeExperiments) {
    const auto it = runs_of.find(experiment);
    if (it == runs_of.end()) continue;
    for (const auto* run : it->second) {
      for (const auto& [name, value] : run->metrics) {
        if (name.rfind("expected_", 0) == 0) found.insert(name.substr(9));
      }
    }
  }
  std::vector<std::string> labels;
  for (const auto& label : kRopeLabelOrder) {
    if (found.erase(label)) labels.push_back(label);
  }
  labels.insert(labels.end(), found.begin(), found.end());  // any other, alphabetically
  labels.push_back(kAllRow);
  return labels;
}

std::string rope_section(const RunsOf& runs_of, CellTable& cells) {
  std::string out =
      "## Rope knotting: task success per correction type\n\n"
      "The paper gives no number to compare with: its real-robot knotting (Section IV-C) "
      "shows the successful and failed test contexts in a figure and reports no success "
      "rate. Each cell: the mean success rate across runs with its 95% interval (over the "
      "runs expecting the correction at least once), then the trials pooled over the runs.\n\n";
  const bool any = std::any_of(kRopeExperiments.begin(), kRopeExperiments.end(),
                               [&](const std::string& e) { return runs_of.count(e) > 0; });
  if (!any) return out + "No rope runs in this selection.\n";
  std::vector<std::string> headings{"Correction"};
  headings.insert(headings.end(), kRopeExperiments.begin(), kRopeExperiments.end());
  out += markdown_header(headings);
  for (const auto& label : rope_labels(runs_of)) {
    std::vector<std::string> row{label};
    for (const auto& experiment : kRopeExperiments) {
      const auto it = runs_of.find(experiment);
      const auto runs = it == runs_of.end() ? std::vector<const RunSummary*>{} : it->second;
      const std::string metric =
          label == kAllRow ? "task_success_rate" : "task_success_rate_" + label;
      const Cell rate =
          cells.add(metric_cell("rope", label, experiment, metric, runs, true, {}, 0.0, true));
      const Cell pooled = cells.add(pooled_cell("rope", label, experiment, runs));
      row.push_back(rate.runs == 0 ? rate.ours : rate.ours + " · pooled " + pooled.ours);
    }
    out += markdown_row(row);
  }
  return out;
}

std::string csv_text(const CellTable& cells) {
  std::string out = "table,row,group,quantity,runs,mean,ci_low,ci_high,ours,paper,verdict\n";
  for (const auto& c : cells.cells()) {
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", c.table, csv_cell(c.row),
                       csv_cell(c.group), csv_cell(c.quantity), c.runs, csv_number(c.mean),
                       csv_number(c.low), csv_number(c.high), csv_cell(c.ours), csv_cell(c.paper),
                       csv_cell(c.verdict));
  }
  return out;
}

}  // namespace

std::string reproduction_verdict(int runs, double low, double high, double paper,
                                 double paper_rounding, bool higher_is_better) {
  if (runs == 0) return "no runs";
  if (runs == 1 || std::isnan(low) || std::isnan(high)) return "no interval (1 run)";
  if (low > paper + paper_rounding) return higher_is_better ? "better" : "worse";
  if (high < paper - paper_rounding) return higher_is_better ? "worse" : "better";
  return "reproduced";
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

namespace {

// A warning above the tables when the runs are too small for their verdicts to say much: fewer
// trials in a run than the paper's, or fewer than kMinimumSeeds training seeds of an experiment
// (the reproduction runs 5). "" when they are not.
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

ReproductionReport reproduction_report(const ReproductionInputs& inputs) {
  std::vector<std::string> experiments;
  for (const auto& g : kCorridorGroups) experiments.push_back(g.experiment);
  experiments.insert(experiments.end(), kRopeExperiments.begin(), kRopeExperiments.end());
  RunsOf runs_of;
  for (const auto& run : inputs.runs) {
    if (std::find(experiments.begin(), experiments.end(), run.experiment) != experiments.end()) {
      runs_of[run.experiment].push_back(&run);
    }
  }
  if (runs_of.empty()) {
    throw ReproductionError(
        "the selected runs hold none of the paper's experiments (corridor_pc, corridor_ae, "
        "corridor_mono, rope_color, rope_perfect, rope_nocorrection, rope_mono)");
  }
  const YAML::Node tables = YAML::LoadFile(inputs.paper_tables);

  std::string md = "# Reproduction of the paper's results\n\n";
  if (inputs.sweep) {
    const SweepSummary& s = *inputs.sweep;
    md += fmt::format("Sweep `{}`", s.id);
    if (!s.name.empty())
      md += fmt::format(" ({}, created {}, {} jobs)", s.name, s.created_at, s.jobs);
    md += fmt::format(": {} runs read.\n\n", inputs.runs.size());
  }
  md += scale_note(runs_of, static_cast<int>(paper_expected_trials(tables)));
  md += "## Runs\n\n" + runs_section(runs_of, experiments, inputs.runs);
  md +=
      "\n## How to read the tables\n\n"
      "Each of our cells is the mean across the runs (seeds) with its 95% confidence interval "
      "[low, high] (Student t, n - 1 degrees of freedom; intervals clipped to the values a metric "
      "can take: errors at 0, rates to [0, 100]%). "
      "With one run there is no interval. A rate per expected correction is averaged over the "
      "runs that expected that correction at least once; (n=k) marks fewer runs than the "
      "group has. The paper's number is beside each cell (assets/paper/tables.yaml). Verdict: "
      "reproduced when the paper's number, within half its last printed digit, lies inside our "
      "interval; better or worse when the interval lies entirely on that side (higher is "
      "better for rates, lower for errors).\n\n";
  CellTable cells;
  const bool corridor =
      std::any_of(kCorridorGroups.begin(), kCorridorGroups.end(),
                  [&](const CorridorGroup& g) { return runs_of.count(g.experiment); });
  md += corridor ? corridor_sections(runs_of, tables, cells)
                 : "## Tables I and II (push through the corridor)\n\nNo corridor runs in this "
                   "selection.\n";
  md += "\n" + rope_section(runs_of, cells);
  md += "\n" + figures_section(inputs.figures, inputs.figure_notes);
  return {md, csv_text(cells)};
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
