// The reproduction report: our runs beside a reference's published numbers.
// After the runs read and how to read the cells, the reference's decision
// and error tables (decision_tables.hpp), then the success per label of the
// experiments it gives no number for (label_success_table.hpp), then the
// share of trials lost per failure category of every selected experiment
// (failure_share_table.hpp), then the figures. Which experiments, labels, numbers and texts are
// data (ReproductionSpec); written as report.md and report.csv with the same cells.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "report/decision_tables.hpp"
#include "report/label_success_table.hpp"
#include "report/reproduction_figures.hpp"
#include "report/run_summaries.hpp"

namespace corrmp {

class ReproductionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ReproductionSpec {
  std::string title;             // the report's heading
  std::string reference_source;  // where the reference's numbers are kept, named in the report
  DecisionTablesSpec decision_tables;
  LabelSuccessSpec label_success;
  ReproductionFiguresSpec figures;

  template <class Fields>
  void describe(Fields& f) {
    f("title", title, "the report's heading", required());
    f("reference_source", reference_source, "where the reference's numbers are kept", required());
    f("decision_tables", decision_tables, "the reference's decision and error tables", required());
    f("label_success", label_success, "success per label of experiments without numbers",
      required());
    f("figures", figures, "the figures besides those of every report", required());
  }
};

struct ReproductionInputs {
  std::vector<RunSummary> runs;  // e.g. a sweep's completed runs; other experiments are listed only
  std::optional<SweepSummary> sweep;      // named in the report's heading when set
  std::vector<ReportFigure> figures;      // see figures_section
  std::vector<std::string> figure_notes;  // figures skipped, and why
};

struct ReproductionReport {
  std::string markdown;  // report.md
  std::string csv;       // report.csv: one row per cell
};

// The spec's experiments: the decision tables' columns, then the label
// success table's.
std::vector<std::string> reproduction_experiments(const ReproductionSpec& spec);

// Throws ReproductionError when the runs hold none of the spec's experiments.
ReproductionReport reproduction_report(const ReproductionSpec& spec,
                                       const ReproductionInputs& inputs);

// Writes directory/report.md and directory/report.csv (creating the folder).
void write_reproduction_report(const ReproductionReport& report, const std::string& directory);

// The report's "Figures" section: one Markdown image with its caption per
// figure, in the order given, then the notes (figures skipped for missing
// inputs) as a list. The figures themselves (reproduction_figures(), with
// the spec's figures) are made and listed by the caller in
// ReproductionInputs::figures and ::figure_notes.
std::string figures_section(const std::vector<ReportFigure>& figures,
                            const std::vector<std::string>& notes = {});

}  // namespace corrmp
