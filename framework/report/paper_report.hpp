// The paper-reproduction report: the paper's Table I (action
// choice, decision match and task success per expected correction) and Table
// II (cor-MP and post-MP mean and max errors) for the corridor PC, AE and Mono
// experiments, each cell the mean across runs (seeds) with its 95% Student t
// interval beside the paper's number (assets/paper/tables.yaml) and a verdict;
// then the rope knotting experiments' success per correction type, which the
// paper gives no number for (Section IV-C); then the figures. Written as
// report.md and report.csv with the same cells.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/run_summaries.hpp"

namespace corrmp {

class ReproductionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A figure of the report: its path (relative to the report's folder, or
// absolute) and its caption.
struct ReportFigure {
  std::string path;
  std::string caption;
};

struct ReproductionInputs {
  std::vector<RunSummary> runs;  // e.g. a sweep's completed runs; other experiments are listed only
  std::string paper_tables;      // assets/paper/tables.yaml
  std::optional<SweepSummary> sweep;      // named in the report's heading when set
  std::vector<ReportFigure> figures;      // see figures_section
  std::vector<std::string> figure_notes;  // figures skipped, and why
};

struct ReproductionReport {
  std::string markdown;  // report.md
  std::string csv;       // report.csv: one row per cell
};

// Throws ReproductionError when the runs hold none of the paper's experiments
// (corridor_pc, corridor_ae, corridor_mono, rope_color, rope_perfect,
// rope_nocorrection, rope_mono).
ReproductionReport reproduction_report(const ReproductionInputs& inputs);

// Writes directory/report.md and directory/report.csv (creating the folder).
void write_reproduction_report(const ReproductionReport& report, const std::string& directory);

// ---- FIGURES -------------------------------------------------------------
// The report's "Figures" section: one Markdown image with its caption per
// figure, in the order given, then the notes (figures skipped for missing
// inputs) as a list. The figures themselves (plots of the runs,
// reproduction_figures.hpp) are made and listed by the caller: `report
// --reproduction` passes them in ReproductionInputs::figures and
// ::figure_notes.
std::string figures_section(const std::vector<ReportFigure>& figures,
                            const std::vector<std::string>& notes = {});

// The verdict on one cell: "reproduced" when the paper's value, widened by
// half its last printed digit (`paper_rounding`), meets our interval [low,
// high]; "better" or "worse" when the interval lies entirely on that side
// (higher is better for rates, lower for errors); "no interval (1 run)" with
// one run; "no runs" with none.
std::string reproduction_verdict(int runs, double low, double high, double paper,
                                 double paper_rounding, bool higher_is_better);

}  // namespace corrmp
