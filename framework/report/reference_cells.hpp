// Cells of our runs beside reference numbers (a publication's), for the
// reproduction report: a metric's mean across runs with its 95% interval, the
// reference's value and a verdict; trials pooled over runs; the decisions
// chosen per expected label. Every cell is also a row of report.csv.
#pragma once

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/config/field_rule.hpp"
#include "report/run_summaries.hpp"

namespace corrmp {

// The runs of each experiment.
using RunsOf = std::map<std::string, std::vector<const RunSummary*>>;

// A label as the runs record it and as the reference prints it.
struct PrintedLabel {
  std::string name;
  std::string printed;

  template <class Fields>
  void describe(Fields& f) {
    f("name", name, "the label as the runs record it", required());
    f("printed", printed, "the label as the reference prints it", required());
  }
};

// The row name of the cells over all trials (not one label's).
inline const std::string kAllTrialsRow = "all";

// One of our numbers beside the reference's: a row of report.csv and a cell
// (with its reference value and verdict) of report.md.
struct ReportCell {
  std::string table, row, group, quantity;
  int runs = 0;
  double mean = NAN, low = NAN, high = NAN;
  std::string ours, paper, verdict;
};

class ReportCells {
 public:
  // Records the cell and returns a copy (a reference would not outlive the next add).
  ReportCell add(ReportCell cell);
  const std::vector<ReportCell>& cells() const { return cells_; }
  // table,row,group,quantity,runs,mean,ci_low,ci_high,ours,paper,verdict: one row per cell.
  std::string csv() const;

 private:
  std::vector<ReportCell> cells_;
};

// The verdict on one cell: "reproduced" when the reference value, widened by
// half its last printed digit (`paper_rounding`), meets our interval [low,
// high]; "better" or "worse" when the interval lies entirely on that side
// (higher is better for rates, lower for errors); "no interval (1 run)" with
// one run; "no runs" with none.
std::string reproduction_verdict(int runs, double low, double high, double paper,
                                 double paper_rounding, bool higher_is_better);

// A metric across runs: its mean with the interval clipped to the values the
// metric can take (metric_ranges.hpp), in percent or with two decimals, beside
// the reference value (printed alike) with its verdict; without a reference
// value the verdict says so.
ReportCell metric_cell(const std::string& table, const std::string& row, const std::string& group,
                       const std::string& metric, const std::vector<const RunSummary*>& runs,
                       bool percent, const std::optional<double>& paper, double rounding,
                       bool higher_is_better);

// The pooled success of the trials expecting `row` (kAllTrialsRow: of all
// trials) over the runs, with a Wilson interval.
ReportCell pooled_cell(const std::string& table, const std::string& row, const std::string& group,
                       const std::vector<const RunSummary*>& runs);

// The decisions the runs chose in the trials expecting `expected`, pooled and
// most frequent first, printed with `labels` ("5 Push, 1 No Correction (3
// runs)"), beside the reference's printed cell.
ReportCell action_choice_cell(const std::string& table, const std::string& group,
                              const std::string& expected,
                              const std::vector<const RunSummary*>& runs,
                              const std::vector<PrintedLabel>& labels, const std::string& paper);

// A Markdown table row, and a heading row with its rule.
std::string markdown_row(const std::vector<std::string>& cells);
std::string markdown_header(const std::vector<std::string>& headings);

}  // namespace corrmp
