// Ctrl-C during a run: run_experiment stops at the next safe point, records the run as
// 'interrupted' with its reason, and exits 130; nothing is left 'running'.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <thread>

#include "config/test_files.hpp"
#include "store/result_store.hpp"
#include "support/child_process.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

TEST(InterruptedRun, CtrlCRecordsTheRunAsInterruptedAndExits130) {
  TempDir dir;
  const std::string config = dir.write(
      "slow.yaml",
      "experiment: {name: slow}\ndemonstrations: {type: curve_family, train: 4, validation: 2, "
      "time_steps: 10}\npolicy:\n  type: segmented_cnmp\n  network: {width: 8}\n"
      "  training: {updates: 100000000, validate_every: 1000}\n");
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
  EXPECT_EQ(store.query_int("SELECT count(*) FROM runs"), 1);
  EXPECT_EQ(store.query_text("SELECT status FROM runs"), "interrupted");
}

}  // namespace
}  // namespace corrmp
