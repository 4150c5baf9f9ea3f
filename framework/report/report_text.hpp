// Cells of the report tables (run, comparison and paper-reproduction reports):
// escaping for Markdown and CSV and the printed form of numbers, means with
// their confidence intervals and pooled proportions.
#pragma once

#include <string>

#include "stats/mean_interval.hpp"
#include "stats/wilson_interval.hpp"

namespace corrmp {

// Text inside a Markdown table cell: a '|' would end the cell.
std::string markdown_cell(const std::string& text);
// A CSV field, quoted when it holds a comma, quote or line break.
std::string csv_cell(const std::string& text);

// A number with `decimals` decimals, or three significant digits when it is
// below 0.1 and not 0 (errors of a few millimetres in metres).
std::string fixed_number(double value, int decimals);
// fixed_number with three decimals (four significant digits from 1000 on); "-"
// for NaN.
std::string report_number(double value);
// A CSV number at full precision; empty for NaN.
std::string csv_number(double value);

// "0.960 [0.861, 1.000]": the mean and its interval's bounds as given (e.g.
// clipped, metric_ranges.hpp); "0.700 (1 run, no interval)" with one run;
// "-" with none.
std::string mean_with_interval(const MeanInterval& m, double low, double high);
// "72 of 75 (96.0%, 95% CI 89.0-98.6%)" (Wilson); "no trials" without any.
std::string pooled_success_text(const ProportionInterval& p);

}  // namespace corrmp
