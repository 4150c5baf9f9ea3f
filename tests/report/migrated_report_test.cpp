// The report of a database an older build wrote (tests/store/fixtures/schema_v3.sqlite, written by
// run_experiment before metrics and tasks were declared) is the report that build gave of it
// (the fixture's .md and .csv files), though this build migrates the database and reads the
// metrics' meaning from their declarations instead of their names.
#include <gtest/gtest.h>

#include <filesystem>

#include "config/test_files.hpp"
#include "support/report_tool.hpp"

namespace corrmp {
namespace {

using testing::TempDir;
using testing::ToolOutcome;

const std::string kFixtures = std::string(PROJECT_DIR) + "/tests/store/fixtures/";

TEST(MigratedReport, ADatabaseOfTheEarlierSchemaReportsTheTablesItDidBefore) {
  TempDir dir;
  std::filesystem::copy_file(kFixtures + "schema_v3.sqlite", dir.file("r.sqlite"));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "schema_v3.report.md"},
      {"--csv", "schema_v3.report.csv"},
      {"--compare", "schema_v3.compare.md"},
      {"--compare --csv", "schema_v3.compare.csv"},
  };
  for (const auto& [args, expected] : cases) {
    const ToolOutcome outcome = testing::report_tool(dir, args);
    EXPECT_EQ(outcome.exit_code, 0) << args << "\n" << outcome.err;
    EXPECT_EQ(outcome.out, testing::read(kFixtures + expected)) << args;
  }
  // No task declaration: the decisions are listed as the trials first expected them.
  const ToolOutcome decisions = testing::report_tool(dir, "--decisions --run 1");
  EXPECT_EQ(decisions.exit_code, 0) << decisions.err;
  EXPECT_NE(decisions.out.find("| 1 | corridor_pc | push | 3 |"), std::string::npos)
      << decisions.out;
  EXPECT_LT(decisions.out.find("| push |"), decisions.out.find("| pull |")) << decisions.out;
  const ToolOutcome both = testing::report_tool(dir, "--decisions --compare");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_EQ(both.err,
            "report: --decisions is a table of its own: drop --compare, --reproduction, --paper "
            "and --plot-success\n");
}

}  // namespace
}  // namespace corrmp
