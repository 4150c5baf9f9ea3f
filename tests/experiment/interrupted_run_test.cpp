// Ctrl-C during a run: run_experiment stops at the next safe point, records the run as
// 'interrupted' with its reason, and exits 130; nothing is left 'running'.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "config/test_files.hpp"
#include "store/result_store.hpp"

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
  const pid_t child = fork();
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    execl(RUN_EXPERIMENT_BIN, RUN_EXPERIMENT_BIN, config.c_str(), "--db",
          dir.file("r.sqlite").c_str(), "--out", dir.file("runs").c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Interrupt once the run is recorded and training.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int64_t running = 0;
  while (running == 0 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (!std::filesystem::exists(dir.file("r.sqlite"))) continue;
    try {
      ResultStore store(dir.file("r.sqlite"));
      running = store.query_int("SELECT count(*) FROM runs WHERE status = 'running'");
    } catch (const StoreError&) {
    }
  }
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
