// Ctrl-C during a run: run_experiment stops at the next safe point, records the run as
// 'interrupted' with its reason, and exits 130; nothing is left 'running'. kill -9 during a run:
// the next process to open the database marks it 'interrupted' there and in its run.json.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "config/test_files.hpp"
#include "experiment/interrupted_runs.hpp"
#include "store/result_store.hpp"
#include "support/child_process.hpp"
#include "support/store_sql.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

const char* kSlowConfig =
    "experiment: {name: slow}\ndemonstrations: {type: curve_family, train: 4, validation: 2, "
    "time_steps: 10}\npolicy:\n  type: segmented_cnmp\n  network: {width: 8}\n"
    "  training: {updates: 100000000, validate_every: 1000}\n";

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(InterruptedRun, CtrlCRecordsTheRunAsInterruptedAndExits130) {
  TempDir dir;
  const std::string config = dir.write("slow.yaml", kSlowConfig);
  const pid_t child = testing::spawn_quietly(
      {RUN_EXPERIMENT_BIN, config, "--db", dir.file("r.sqlite"), "--out", dir.file("runs")});
  // Interrupt once the run is recorded and training.
  const int64_t running = testing::wait_until_positive(
      dir.file("r.sqlite"), "SELECT count(*) FROM runs WHERE status = 'running'");
  ASSERT_EQ(running, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(child, SIGINT);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(testing::query_int(store, "SELECT count(*) FROM runs"), 1);
  EXPECT_EQ(testing::query_text(store, "SELECT status FROM runs"), "interrupted");
}

TEST(InterruptedRun, AKilledRunIsMarkedInterruptedInTheDatabaseAndItsRunJson) {
  TempDir dir;
  const std::string config = dir.write("slow.yaml", kSlowConfig);
  const pid_t child = testing::spawn_quietly(
      {RUN_EXPERIMENT_BIN, config, "--db", dir.file("r.sqlite"), "--out", dir.file("runs")});
  const std::string run_json = dir.file("runs/slow/1/run.json");
  ASSERT_EQ(testing::wait_until_positive(dir.file("r.sqlite"),
                                         "SELECT count(*) FROM runs WHERE out_dir IS NOT NULL"),
            1);
  for (int i = 0; i < 600 && !std::filesystem::exists(run_json); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  ASSERT_NE(read_text(run_json).find("\"status\": \"running\""), std::string::npos);

  ResultStore store(dir.file("r.sqlite"));
  EXPECT_EQ(mark_interrupted_runs(store), 1);
  EXPECT_EQ(testing::query_text(store, "SELECT status FROM runs"), "interrupted");
  const std::string json = read_text(run_json);
  EXPECT_NE(json.find("\n  \"status\": \"interrupted\",\n"), std::string::npos) << json;
  EXPECT_NE(json.find("\n  \"finished_at\": \"" +
                      testing::query_text(store, "SELECT finished_at FROM runs") + "\",\n"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\n  \"failure\": \"the process running it ended without finishing\",\n"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"libraries\""), std::string::npos) << json;  // the rest kept
  EXPECT_EQ(mark_interrupted_runs(store), 0);
}

// A run.json that is missing, or not as the pipeline writes it, is left alone.
TEST(InterruptedRun, ARunJsonNotAsThePipelineWritesItIsLeftAlone) {
  TempDir dir;
  EXPECT_FALSE(mark_run_json_interrupted(dir.file("none.json"), "t", "f"));
  const std::string edited = dir.write("run.json", "{\n  \"status\": \"completed\"\n}\n");
  EXPECT_FALSE(mark_run_json_interrupted(edited, "t", "f"));
  EXPECT_EQ(read_text(edited), "{\n  \"status\": \"completed\"\n}\n");
}

}  // namespace
}  // namespace corrmp
