// A sweep's job array through a real single-node Slurm (tests/support/local_slurm.sh):
// sbatch runs every task with its arguments and log files, --wait reports a failed
// task's exit status, and resubmitting only that task resumes the sweep. The program
// the array runs is a recorder standing in for run_experiment. Skipped where Slurm
// cannot start (not installed, not root). docs/slurm.md.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "config/test_files.hpp"
#include "support/local_slurm.hpp"
#include "sweep/slurm_launcher.hpp"

namespace corrmp {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using testing::LocalSlurm;
using testing::TempDir;
using ::testing::ThrowsMessage;

// Records its arguments, one a line, per array task and counts the task's runs; task
// 2 fails (exit 3) on its first run only.
constexpr const char* kRecorder = R"sh(#!/bin/bash
set -euo pipefail
records="$(dirname "$0")/../records"
printf '%s\n' "$@" > "$records/task-$SLURM_ARRAY_TASK_ID.args"
echo run >> "$records/task-$SLURM_ARRAY_TASK_ID.runs"
echo "task $SLURM_ARRAY_TASK_ID ran"
if [ "$SLURM_ARRAY_TASK_ID" = 2 ] && [ "$(wc -l < "$records/task-2.runs")" -eq 1 ]; then
  echo "task 2 fails once" >&2
  exit 3
fi
)sh";

std::vector<std::string> lines_of_file(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) lines.push_back(line);
  return lines;
}

std::string write_script(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

TEST(SlurmRoundTrip, RunsEveryArrayTaskWithItsArgumentsAndResumesTheFailedOne) {
  TempDir dir;
  LocalSlurm slurm(dir.file("slurm"));
  if (!slurm.running()) {
    if (slurm.unavailable()) GTEST_SKIP() << slurm.reason();
    FAIL() << slurm.reason();
  }

  // Every path of the sweep holds a space and both quotes.
  const std::filesystem::path base = dir.path() / "sweep 'one' \"two\"";
  for (const char* sub : {"bin", "records", "shards", "out", "logs"}) {
    std::filesystem::create_directories(base / sub);
  }
  const std::string recorder = write_script(base / "bin" / "run experiment", kRecorder);
  ASSERT_EQ(::chmod(recorder.c_str(), 0755), 0);

  Sweep sweep;
  sweep.id = "roundtrip-test";
  sweep.name = "roundtrip";
  sweep.jobs.resize(4);
  const long cpus = ::sysconf(_SC_NPROCESSORS_ONLN);
  sweep.slurm.cpus_per_task = cpus >= 2 ? 2 : 1;
  sweep.slurm.time = "00:05:00";
  sweep.slurm.memory = "64M";
  sweep.slurm.partition = "debug";
  const SlurmPaths paths = {recorder, (base / "manifest.json").string(), (base / "shards").string(),
                            (base / "out").string(), (base / "logs").string()};

  const SlurmSubmission first =
      submit_slurm(write_script(base / "array.sbatch", slurm_array_script(sweep, paths)), true);
  EXPECT_FALSE(first.job_id.empty());
  ASSERT_TRUE(first.exit_code.has_value());
  EXPECT_EQ(*first.exit_code, 3) << "sbatch --wait reports the highest exit status of the tasks";

  for (int task = 0; task < 4; ++task) {
    const std::string index = std::to_string(task);
    const std::vector<std::string> expected = {"--sweep-job",
                                               paths.manifest,
                                               index,
                                               "--db",
                                               paths.shard_dir + "/job-" + index + ".sqlite",
                                               "--out",
                                               paths.out_dir,
                                               "--threads",
                                               std::to_string(sweep.slurm.cpus_per_task),
                                               "--quiet"};
    EXPECT_EQ(lines_of_file(base / "records" / ("task-" + index + ".args")), expected)
        << "task " << task;
    EXPECT_EQ(lines_of_file(base / "records" / ("task-" + index + ".runs")).size(), 1u);
    EXPECT_EQ(lines_of_file(base / "logs" / ("job-" + index + ".out")),
              std::vector<std::string>{"task " + index + " ran"});
  }
  EXPECT_EQ(lines_of_file(base / "logs" / "job-2.err"),
            std::vector<std::string>{"task 2 fails once"});

  SlurmArraySelection failed;
  failed.indices = {2};
  const SlurmSubmission resumed = submit_slurm(
      write_script(base / "resume.sbatch", slurm_array_script(sweep, paths, failed)), true);
  EXPECT_NE(resumed.job_id, first.job_id);
  ASSERT_TRUE(resumed.exit_code.has_value());
  EXPECT_EQ(*resumed.exit_code, 0);
  EXPECT_EQ(lines_of_file(base / "records" / "task-2.runs").size(), 2u);
  for (const int task : {0, 1, 3}) {
    EXPECT_EQ(lines_of_file(base / "records" / ("task-" + std::to_string(task) + ".runs")).size(),
              1u)
        << "task " << task << " ran again";
  }
}

TEST(SlurmRoundTrip, SubmitsWithoutWaitingAndReportsWhatSbatchRefuses) {
  TempDir dir;
  LocalSlurm slurm(dir.file("slurm"));
  if (!slurm.running()) {
    if (slurm.unavailable()) GTEST_SKIP() << slurm.reason();
    FAIL() << slurm.reason();
  }
  std::filesystem::create_directories(dir.path() / "logs");
  Sweep sweep;
  sweep.name = "refused";
  sweep.jobs.resize(2);
  sweep.slurm.cpus_per_task = 1;
  sweep.slurm.memory = "64M";
  const SlurmPaths paths = {"/bin/true", dir.file("manifest.json"), dir.file("shards"),
                            dir.file("out"), dir.file("logs")};

  const SlurmSubmission queued =
      submit_slurm(write_script(dir.path() / "ok.sbatch", slurm_array_script(sweep, paths)), false);
  EXPECT_FALSE(queued.job_id.empty());
  EXPECT_FALSE(queued.exit_code.has_value());

  sweep.slurm.partition = "no_such_partition";
  const std::string refused =
      write_script(dir.path() / "refused.sbatch", slurm_array_script(sweep, paths));
  EXPECT_THAT(
      [&] { submit_slurm(refused, true); },
      ThrowsMessage<std::runtime_error>(
          AllOf(HasSubstr("sbatch could not submit " + refused), HasSubstr("Invalid partition"))));
}

}  // namespace
}  // namespace corrmp
