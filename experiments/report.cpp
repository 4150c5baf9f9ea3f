// report [--db PATH] [--experiment NAME ...] [--run ID ...] [--last N] [--csv]
//        [--metric NAME ...] [--paper] [--all]
// Prints one row per recorded run (task success, decision match, cor-MP and
// post-MP errors of the paper's Tables I and II) with the settings that vary
// between runs of the same experiment, as Markdown or CSV.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

#include "command_line.hpp"
#include "experiment/run_report.hpp"

namespace {

constexpr const char* kExamples = R"(
Examples:
  report                                        every completed run
  report --experiment corridor_pc corridor_mono --paper
  report --last 5 --metric demonstrations_train
  report --experiment corridor_mono --csv > mono.csv
)";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Tabulates recorded runs of the correction-primitive framework.", "report"};
  std::string db_path = "results/results.sqlite";
  corrmp::ReportQuery query;
  corrmp::ReportFormat format;
  bool csv = false, paper = false, all = false;
  app.add_option("--db", db_path, "result database")->capture_default_str();
  app.add_option("--experiment", query.experiments, "only these experiments");
  app.add_option("--run", query.runs, "only these run ids");
  app.add_option("--last", query.last, "only the newest N selected runs")
      ->check(CLI::PositiveNumber);
  app.add_option("--metric", format.extra_metrics, "more metric columns, by name");
  app.add_flag("--csv", csv, "CSV instead of Markdown");
  app.add_flag("--paper", paper, "append the paper's rows (Markdown)");
  app.add_flag("--all", all, "include failed, interrupted and running runs");
  app.footer(kExamples);
  if (const auto exit_code = corrmp::parse_command_line(app, argc, argv)) return *exit_code;
  query.completed_only = !all;
  if (paper) format.paper_tables = std::string(CORRMP_SOURCE_DIR) + "/assets/paper/tables.yaml";

  if (!std::filesystem::exists(db_path)) {
    std::cerr << "report: no result database at '" << db_path << "' (see --db)\n";
    return 2;
  }
  try {
    corrmp::ResultStore store(db_path);
    const auto runs = corrmp::load_run_summaries(store, query);
    if (runs.empty()) {
      std::cerr << "report: no run in '" << db_path << "' matches\n";
      return 1;
    }
    std::cout << (csv ? corrmp::report_csv(runs, format) : corrmp::report_markdown(runs, format));
  } catch (const std::exception& e) {
    std::cerr << "report: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
