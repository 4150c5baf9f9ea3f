// Tests of the cells of runs beside reference numbers: the verdicts and the
// decisions chosen, printed with the reference's names.
#include "report/reference_cells.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corrmp {
namespace {

TEST(ReferenceCells, VerdictsAllowForThePapersRounding) {
  EXPECT_EQ(reproduction_verdict(3, 5.0 / 6, 5.0 / 6, 0.83, 0.005, true), "reproduced");
  EXPECT_EQ(reproduction_verdict(3, 0.84, 0.9, 0.83, 0.005, true), "better");
  EXPECT_EQ(reproduction_verdict(3, 0.5, 0.8, 0.83, 0.005, true), "worse");
  EXPECT_EQ(reproduction_verdict(3, 0.5, 0.8, 0.83, 0.005, false), "better");
  EXPECT_EQ(reproduction_verdict(3, 0.96, 0.97, 0.96, 0.0, true), "reproduced");
  EXPECT_EQ(reproduction_verdict(1, NAN, NAN, 0.5, 0.0, true), "no interval (1 run)");
  EXPECT_EQ(reproduction_verdict(0, NAN, NAN, 0.5, 0.0, true), "no runs");
}

// The chosen decisions pooled over the runs, most frequent first, in the reference's names
// (a label it does not name as recorded, no decision as "undecided").
TEST(ReferenceCells, ActionChoicePrintsTheReferencesNames) {
  RunSummary a, b;
  a.by_expected["up"].chosen = {{"up", 2}, {"sideways", 1}};
  b.by_expected["up"].chosen = {{"up", 1}, {"", 1}};
  b.by_expected["down"].chosen = {{"down", 1}};
  const std::vector<PrintedLabel> labels{{"up", "Up"}, {"down", "Down"}};
  const ReportCell cell = action_choice_cell("t", "g", "up", {&a, &b}, labels, "4 Up");
  EXPECT_EQ(cell.ours, "3 Up, 1 undecided, 1 sideways (2 runs)");
  EXPECT_EQ(cell.paper, "4 Up");
  EXPECT_EQ(cell.runs, 2);
  EXPECT_EQ(action_choice_cell("t", "g", "left", {&a}, labels, "").ours, "never expected");
  EXPECT_EQ(action_choice_cell("t", "g", "up", {}, labels, "").ours, "no runs");
}

}  // namespace
}  // namespace corrmp
