// report [--db PATH] [--experiment NAME ...] [--run ID ...] [--sweep ID ...]
//        [--last N] [--csv] [--metric NAME ...] [--paper] [--all] [--decisions]
// report --compare [--by KEY ...] [--baseline GROUP] [--out DIR] ...
// report --reproduction --sweep ID --out DIR
// report --plot-success KEY [--sweep ID ...] --out DIR
// Prints one row per recorded run (task success, decision match and each
// trajectory error the run declared) with the settings that vary
// between runs of the same experiment, as Markdown or CSV; with --decisions,
// each run's decisions by expected label in its task's order (Table I); with --compare,
// groups of runs side by side with means and 95% intervals across seeds and
// Fisher's exact test on their pooled trials (run_comparison.hpp); with
// --reproduction, the paper's Tables I and II against a sweep's runs and its
// figures (reproduction_report.hpp, with the paper's data: paper/paper.hpp); with
// --plot-success, task success against a setting with 95% intervals.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

#include "command_line.hpp"
#include "core/config/config_error.hpp"
#include "core/config/did_you_mean.hpp"
#include "core/path_checks.hpp"
#include "paper/paper.hpp"
#include "report/decision_table.hpp"
#include "report/reproduction_figures.hpp"
#include "report/reproduction_report.hpp"
#include "report/run_comparison.hpp"
#include "report/run_report.hpp"
#include "store/result_store.hpp"

namespace {

constexpr const char* kExamples = R"(
Examples:
  report                                        every completed run
  report --experiment corridor_pc corridor_mono --paper
  report --last 5 --metric demonstrations_train
  report --experiment corridor_pc --decisions    each decision label: action choice, match
  report --experiment corridor_mono --csv > mono.csv
  report --compare --experiment corridor_pc corridor_ae corridor_mono --baseline corridor_mono
  report --compare --sweep SWEEP_ID --by policy.type --out results/compare
  report --reproduction --sweep SWEEP_ID --out results/reproduction
  report --plot-success policy.training.updates --sweep SWEEP_ID --out results/plots
)";

// A usage error: one line naming the tool, exit code 2.
int usage_error(const std::string& message) {
  std::cerr << "report: " << message << "\n";
  return 2;
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream file(path);
  file << text;
  if (!file) throw std::runtime_error("cannot write '" + path.string() + "'");
}

// Every --experiment and --run asked for must have a selected run: a group
// without runs cannot be compared.
std::string missing_selection(const corrmp::ReportQuery& query,
                              const std::vector<corrmp::RunSummary>& runs) {
  for (const auto& experiment : query.experiments) {
    const bool found = std::any_of(runs.begin(), runs.end(),
                                   [&](const auto& run) { return run.experiment == experiment; });
    if (!found) return "experiment '" + experiment + "' has no selected run";
  }
  for (int64_t id : query.runs) {
    const bool found =
        std::any_of(runs.begin(), runs.end(), [&](const auto& run) { return run.id == id; });
    if (!found) return "run " + std::to_string(id) + " is not among the selected runs";
  }
  return "";
}

// "--metric 'NAME': ..." for the first extra metric no selected run recorded (a typo would
// otherwise add a column of '-'); empty when every one is recorded by some run.
std::string unrecorded_metric(const std::vector<corrmp::RunSummary>& runs,
                              const std::vector<std::string>& metrics) {
  for (const auto& metric : metrics) {
    const bool recorded = std::any_of(
        runs.begin(), runs.end(), [&](const auto& run) { return run.metrics.count(metric) > 0; });
    if (recorded) continue;
    std::set<std::string> names;
    for (const auto& run : runs) {
      for (const auto& entry : run.metrics) names.insert(entry.first);
    }
    return "--metric '" + metric + "': no selected run recorded it" +
           corrmp::did_you_mean(metric, std::vector<std::string>(names.begin(), names.end()));
  }
  return "";
}

// "no run in 'DB' matches", or, when only runs that did not complete match (a database of
// failed runs must not look empty): "no completed run in 'DB' matches, but 2 failed and 1
// interrupted do: --all shows them".
std::string no_run_matches(corrmp::ResultStore& store, corrmp::ReportQuery query,
                           const std::string& db_path) {
  std::vector<std::string> counts;
  int total = 0;
  if (query.completed_only) {
    query.completed_only = false;
    std::map<corrmp::RunStatus, int> by_status;
    for (const auto& run : corrmp::load_run_summaries(store, query)) ++by_status[run.status];
    for (const auto status :
         {corrmp::RunStatus::failed, corrmp::RunStatus::interrupted, corrmp::RunStatus::running}) {
      if (by_status[status] == 0) continue;
      counts.push_back(std::to_string(by_status[status]) + " " + corrmp::to_string(status));
      total += by_status[status];
    }
  }
  if (counts.empty()) return "no run in '" + db_path + "' matches";
  std::string listed = counts.front();
  for (size_t i = 1; i < counts.size(); ++i) {
    listed += (i + 1 == counts.size() ? " and " : ", ") + counts[i];
  }
  return "no completed run in '" + db_path + "' matches, but " + listed +
         (total == 1 ? " does" : " do") + ": --all shows them";
}

// A 0-byte regular file: what `touch` leaves, a database with nothing recorded yet.
bool is_empty_file(const std::string& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error) &&
         std::filesystem::file_size(path, error) == 0 && !error;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Tabulates recorded runs of the correction-primitive framework.", "report"};
  std::string db_path = "results/results.sqlite";
  corrmp::ReportQuery query;
  corrmp::ReportFormat format;
  corrmp::ComparisonOptions comparison;
  std::string out_dir, plot_success;
  bool csv = false, paper = false, all = false, compare = false, reproduction = false,
       decisions = false;
  app.add_option("--db", db_path, "result database")->capture_default_str();
  app.add_option("--experiment", query.experiments, "only these experiments");
  app.add_option("--run", query.runs, "only these run ids");
  app.add_option("--sweep", query.sweeps, "only the runs of these sweeps");
  app.add_option("--last", query.last, "only the newest N selected runs")
      ->check(corrmp::positive_number());
  app.add_option("--metric", format.extra_metrics, "more metric columns, by name");
  app.add_flag("--csv", csv, "CSV instead of Markdown");
  app.add_flag("--paper", paper, "append the paper's rows (Markdown; runs of the paper's task)");
  app.add_flag("--all", all, "include failed, interrupted and running runs");
  app.add_flag("--decisions", decisions,
               "each run's trials by expected decision, in its task's label order: action "
               "choice, decision match, task success (Table I)");
  app.add_flag("--compare", compare,
               "compare groups of runs: means with 95% intervals across seeds, Fisher's exact "
               "test on the pooled trials");
  app.add_option("--by", comparison.group_by,
                 "with --compare: group by these settings or sweep axes (default: experiment)");
  app.add_option("--baseline", comparison.baseline,
                 "with --compare: compare this group with every other (default: every pair)");
  app.add_flag("--reproduction", reproduction,
               "write the paper-reproduction report (Tables I and II, rope) to --out");
  app.add_option("--plot-success", plot_success,
                 "plot task success (mean and 95% interval across seeds) against this setting or "
                 "sweep axis ('experiment': per experiment) to --out, one line per group");
  app.add_option("--out", out_dir,
                 "with --compare: write compare.md and compare.csv here; with --reproduction: "
                 "report.md, report.csv and figures/; with --plot-success: "
                 "success_vs_KEY.png and .csv");
  app.footer(kExamples);
  if (const auto exit_code = corrmp::parse_command_line(app, argc, argv)) return *exit_code;
  query.completed_only = !all;
  format.status_column = all;

  if (compare && reproduction)
    return usage_error("--compare and --reproduction exclude each other");
  if (!compare && (!comparison.group_by.empty() || !comparison.baseline.empty())) {
    return usage_error("--by and --baseline need --compare");
  }
  if (csv && paper) return usage_error("--paper's rows are Markdown only: drop --csv or --paper");
  if ((compare || reproduction) && paper) {
    return usage_error("--paper is for the run table; --compare and --reproduction have their own");
  }
  if (decisions && (compare || reproduction || paper || !plot_success.empty())) {
    return usage_error(
        "--decisions is a table of its own: drop --compare, --reproduction, "
        "--paper and --plot-success");
  }
  if (reproduction && out_dir.empty()) return usage_error("--reproduction needs --out DIR");
  if (!plot_success.empty() && out_dir.empty())
    return usage_error("--plot-success needs --out DIR");
  if (!compare && !reproduction && plot_success.empty() && !out_dir.empty()) {
    return usage_error("--out needs --compare or --reproduction");
  }
  if (!out_dir.empty()) {
    if (const std::string in_the_way = corrmp::file_in_the_way(out_dir); !in_the_way.empty()) {
      return usage_error("--out " + out_dir + ": " + in_the_way);
    }
  }
  if (!std::filesystem::exists(db_path)) {
    return usage_error("no result database at '" + db_path + "' (see --db)");
  }
  // A 0-byte file (what `touch` leaves) holds no runs, and opening it would write a schema into
  // it: say so and leave it alone, with the exit code of a database without runs (a selection
  // that must name runs is a usage error, an empty table is not).
  if (is_empty_file(db_path)) {
    std::cerr << "report: " << db_path << ": no runs recorded (empty database)\n";
    const bool needs_runs =
        compare || reproduction || !plot_success.empty() || !query.sweeps.empty();
    return needs_runs ? 2 : 1;
  }
  try {
    corrmp::ResultStore store(db_path);
    std::optional<corrmp::SweepSummary> sweep;
    for (const auto& id : query.sweeps) {
      if (!corrmp::has_sweep_columns(store)) {
        return usage_error("'" + db_path + "' records no sweeps (see --sweep)");
      }
      sweep = corrmp::find_sweep(store, id);
      if (!sweep) return usage_error("unknown sweep id '" + id + "' in '" + db_path + "'");
    }
    const auto runs = corrmp::load_run_summaries(store, query);
    if (compare || reproduction || !plot_success.empty()) {
      if (const std::string missing = missing_selection(query, runs); !missing.empty()) {
        return usage_error(missing);
      }
      if (runs.empty()) return usage_error(no_run_matches(store, query, db_path));
    } else if (runs.empty()) {
      std::cerr << "report: " << no_run_matches(store, query, db_path) << "\n";
      return 1;
    }

    if (const std::string unknown = unrecorded_metric(runs, format.extra_metrics);
        !unknown.empty()) {
      return usage_error(unknown);
    }
    if (!plot_success.empty()) {
      const auto data = corrmp::success_by_parameter(runs, plot_success);
      if (data.series.empty()) {
        return usage_error("no selected run has both a task success rate and a setting '" +
                           plot_success + "'");
      }
      const std::filesystem::path base =
          std::filesystem::path(out_dir) / ("success_vs_" + plot_success);
      std::filesystem::create_directories(out_dir);
      corrmp::write_success_figure(data, base.string() + ".png");
      write_file(base.string() + ".csv", corrmp::success_csv(data));
      std::cout << "report: wrote " << base.string() << ".png and .csv\n";
    }
    if (compare) {
      comparison.extra_metrics = format.extra_metrics;
      const auto result = corrmp::compare_runs(runs, comparison);
      for (const auto& note : corrmp::pooling_notes(result)) {
        std::cerr << "report: warning: " << note << " (averaged as if seeds)\n";
      }
      if (out_dir.empty()) {
        std::cout << (csv ? corrmp::comparison_csv(result) : corrmp::comparison_markdown(result));
      } else {
        write_file(std::filesystem::path(out_dir) / "compare.md",
                   corrmp::comparison_markdown(result));
        write_file(std::filesystem::path(out_dir) / "compare.csv", corrmp::comparison_csv(result));
        std::cout << "report: wrote " << out_dir << "/compare.md and compare.csv\n";
      }
    } else if (reproduction) {
      const corrmp::ReproductionSpec spec = corrmp::load_paper();
      corrmp::ReproductionInputs inputs;
      inputs.runs = runs;
      if (query.sweeps.size() == 1) inputs.sweep = sweep;
      // FIGURES: the report's figures go in inputs.figures (path relative to
      // out_dir, caption); figures_section (reproduction_report.hpp) lists them.
      corrmp::reproduction_report(spec, inputs);  // refuses runs without the paper's experiments
      corrmp::FigureSet figures = corrmp::reproduction_figures(
          runs, corrmp::load_run_files(store, runs), out_dir, spec.figures);
      inputs.figures = std::move(figures.figures);
      inputs.figure_notes = std::move(figures.notes);
      corrmp::write_reproduction_report(corrmp::reproduction_report(spec, inputs), out_dir);
      std::cout << "report: wrote " << out_dir << "/report.md and report.csv\n";
    } else if (decisions) {
      std::cout << (csv ? corrmp::decision_csv(runs) : corrmp::decision_markdown(runs));
    } else if (plot_success.empty()) {
      if (paper) {
        const corrmp::DecisionTablesSpec tables = corrmp::load_paper().decision_tables;
        if (corrmp::reference_rows_apply(runs, tables)) {
          format.reference_rows = corrmp::reference_rows(tables);
          format.reference_columns = corrmp::reference_columns(tables);
        } else {
          std::cerr << "report: --paper: the paper's numbers are of the task " << tables.environment
                    << ", and no selected run is; none appended\n";
        }
      }
      std::cout << (csv ? corrmp::report_csv(runs, format) : corrmp::report_markdown(runs, format));
    }
  } catch (const corrmp::ComparisonError& e) {
    return usage_error(e.what());
  } catch (const corrmp::ReproductionError& e) {
    return usage_error(e.what());
  } catch (const corrmp::ConfigError& e) {
    // The paper's data (assets/paper/) does not read: bad input, named at its file and line.
    std::cerr << "report: " << e.what() << "\n";
    return 2;
  } catch (const corrmp::StoreError& e) {
    // A database that cannot be used (damaged, a directory, not SQLite) is bad input.
    std::cerr << "report: " << e.what() << "\n";
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    // An output folder or file that cannot be made (no permission, say) is bad input.
    std::cerr << "report: " << e.path1().string() << ": " << e.code().message() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "report: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
