// Tests of the paper's rows below the run table (report --paper): its PC, AE
// and Mono numbers from assets/paper/tables.yaml, for runs of its task only.
#include <gtest/gtest.h>

#include "config/test_files.hpp"
#include "paper/paper.hpp"
#include "report/run_report.hpp"
#include "support/recorded_runs.hpp"

namespace corrmp {
namespace {

using testing::record_scored_run;
using testing::TempDir;

const DecisionTablesSpec& tables() {
  static const DecisionTablesSpec spec =
      load_paper(std::string(PROJECT_DIR) + "/assets/paper").decision_tables;
  return spec;
}

TEST(PaperRows, AppendsThePapersRows) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_scored_run(store, "corridor_pc", "environment: {type: corridor_push}\nseed: 0\n", 1.0,
                    0.2);
  ReportFormat format;
  EXPECT_TRUE(reference_rows_apply(load_run_summaries(store, {}), tables()));
  format.reference_rows = reference_rows(tables());
  const std::string markdown = report_markdown(load_run_summaries(store, {}), format);
  EXPECT_NE(markdown.find("| | paper: pc | | 24 of 25 | 100% | 0.80 / 1.45 | 1.69 / 3.19 |"),
            std::string::npos)
      << markdown;
  // The paper's AE decision match: 8 of 9 push, 6 of 6 none, 9 of 10 pull.
  EXPECT_NE(markdown.find("| | paper: ae | | 25 of 25 | 92% | 0.80 / 0.99 | 2.64 / 4.83 |"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| | paper: mono | | 17 of 25 | 100% | 1.30 / 1.92 | 5.75 / 7.24 |"),
            std::string::npos)
      << markdown;
  // The arms' columns share the floating gripper's numbers: one row each, not two.
  size_t pc_rows = 0;
  for (size_t at = markdown.find("paper: pc |"); at != std::string::npos;
       at = markdown.find("paper: pc |", at + 1))
    ++pc_rows;
  EXPECT_EQ(pc_rows, 1u) << markdown;
  EXPECT_EQ(reference_rows(tables()).size(), 3u);
  format.status_column = true;  // the paper's rows leave the status empty
  const std::string with_status = report_markdown(load_run_summaries(store, {}), format);
  EXPECT_NE(with_status.find("| | paper: pc | | | 24 of 25 | 100% | 0.80 / 1.45 | 1.69 / 3.19 |"),
            std::string::npos)
      << with_status;
}

// An error of the paper's that no selected run recorded still gets its column, headed as the
// runs' own would be.
TEST(PaperRows, AnErrorNoRunRecordedIsHeadedWithItsUnit) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_scored_run(store, "corridor_pc", "environment: {type: corridor_push}\nseed: 0\n", 1.0,
                    0.2);
  ReportFormat format;
  format.reference_rows = reference_rows(tables());
  format.reference_columns = reference_columns(tables());
  const std::string markdown = report_markdown(load_run_summaries(store, {}), format);
  EXPECT_NE(markdown.find("| post-MP error mean / max (cm) |"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| | paper: pc | | 24 of 25 | 100% | 0.80 / 1.45 | 1.69 / 3.19 |"),
            std::string::npos)
      << markdown;
}

// The paper's numbers are of the corridor: a selection of another task's runs gets none.
TEST(PaperRows, AppendsNoPaperRowsToRunsOfAnotherTask) {
  TempDir dir;
  ResultStore store(dir.file("r.sqlite"));
  record_scored_run(store, "rope_color", "environment: {type: rope_knot}\nseed: 0\n", 1.0, 0.2);
  ReportFormat format;
  const auto runs = load_run_summaries(store, {});
  EXPECT_FALSE(reference_rows_apply(runs, tables()));
  if (reference_rows_apply(runs, tables())) format.reference_rows = reference_rows(tables());
  const std::string markdown = report_markdown(runs, format);
  EXPECT_EQ(markdown.find("paper:"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| rope_color |"), std::string::npos) << markdown;
}

}  // namespace
}  // namespace corrmp
