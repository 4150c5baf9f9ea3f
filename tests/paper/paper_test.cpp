// Tests of the paper's data (assets/paper/) as the paper module reads it: its
// columns, experiments and figures; a damaged copy refused at its file and
// line; and `report --paper` appending its rows or saying why not.
#include "paper/paper.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/test_files.hpp"
#include "store/result_store.hpp"

namespace corrmp {
namespace {

using testing::config_error_of;
using testing::TempDir;

const std::string kPaper = std::string(PROJECT_DIR) + "/assets/paper";

std::string read(const std::string& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

TEST(Paper, NamesItsColumnsExperimentsAndFigures) {
  const ReproductionSpec paper = load_paper(kPaper);
  EXPECT_EQ(paper.decision_tables.environment, "corridor_push");
  EXPECT_EQ(
      reproduction_experiments(paper),
      (std::vector<std::string>{"corridor_pc", "corridor_ae", "corridor_mono", "corridor_pc_arms",
                                "corridor_ae_arms", "corridor_mono_arms", "rope_color",
                                "rope_perfect", "rope_nocorrection", "rope_mono", "rope_color_arms",
                                "rope_nocorrection_arms", "rope_mono_arms"}));
  EXPECT_EQ(reference_trials(paper.decision_tables), 25);
  ASSERT_EQ(paper.figures.trajectory_comparisons.size(), 3u);
  EXPECT_EQ(paper.figures.trajectory_comparisons[0].view.unit, "cm");
  EXPECT_EQ(paper.figures.trajectory_comparisons[0].view.scale, 100.0);
  ASSERT_EQ(paper.figures.copied.size(), 4u);
  EXPECT_EQ(paper.figures.copied[1].file, "knotting.png");
  EXPECT_EQ(load_paper().title, paper.title);  // the source tree's copy by default
}

TEST(Paper, ADamagedCopyIsRefusedAtItsFileAndLine) {
  TempDir dir;
  const std::string report = read(kPaper + "/report.yaml");
  std::string tables = read(kPaper + "/tables.yaml");
  dir.write("report.yaml", report);
  const std::string pc_rates =
      "task_success_rate: &pc_success {push: 1.00, none: 0.83, pull: 1.00}";
  const size_t at = tables.find(pc_rates);
  ASSERT_NE(at, std::string::npos);
  dir.write("tables.yaml", tables.substr(0, at) +
                               "task_success_rate: &pc_success {push: 1.00, none: 0.83}" +
                               tables.substr(at + pc_rates.size()));
  const std::string error = config_error_of([&] { load_paper(dir.path().string()); });
  EXPECT_EQ(error.rfind(dir.file("tables.yaml") + ":", 0), 0u) << error;
  EXPECT_NE(error.find(": decision_tables.columns[0].task_success_rate: no value for the label "
                       "'pull'"),
            std::string::npos)
      << error;

  dir.write("report.yaml", report + "legend: below\n");
  dir.write("tables.yaml", tables);
  EXPECT_NE(config_error_of([&] { load_paper(dir.path().string()); }).find("legend: unknown key"),
            std::string::npos);
}

struct ToolOutcome {
  int exit_code = -1;
  std::string out, err;
};

ToolOutcome report_tool(const TempDir& dir, const std::string& args) {
  const std::string out = dir.file("out.txt"), err = dir.file("err.txt");
  const int status =
      std::system((std::string(REPORT_BIN) + " " + args + " >" + out + " 2>" + err).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(out), read(err)};
}

void add_run(ResultStore& store, const std::string& experiment, const std::string& environment) {
  const int64_t id = store.begin_run({experiment, "environment: {type: " + environment + "}\n",
                                      "hash", 0, "", false, "", "", 0, ""});
  store.complete_run(id, {}, {{"task_success_rate", 1.0}});
}

// The paper's numbers are of the corridor: appended below its runs, refused with a notice
// below another task's.
TEST(Paper, TheReportToolAppendsThePapersRowsToRunsOfItsTaskOnly) {
  TempDir dir;
  {
    ResultStore store(dir.file("r.sqlite"));
    add_run(store, "corridor_pc", "corridor_push");
    add_run(store, "rope_color", "rope_knot");
  }
  const ToolOutcome corridor =
      report_tool(dir, "--db " + dir.file("r.sqlite") + " --experiment corridor_pc --paper");
  EXPECT_EQ(corridor.exit_code, 0) << corridor.err;
  EXPECT_NE(corridor.out.find("| | paper: pc | | 24 of 25 | 100% |"), std::string::npos)
      << corridor.out;
  EXPECT_EQ(corridor.err, "");
  const ToolOutcome rope =
      report_tool(dir, "--db " + dir.file("r.sqlite") + " --experiment rope_color --paper");
  EXPECT_EQ(rope.exit_code, 0) << rope.err;
  EXPECT_EQ(rope.out.find("paper:"), std::string::npos) << rope.out;
  EXPECT_EQ(rope.err,
            "report: --paper: the paper's numbers are of the task corridor_push, and no selected "
            "run is; none appended\n");
}

}  // namespace
}  // namespace corrmp
