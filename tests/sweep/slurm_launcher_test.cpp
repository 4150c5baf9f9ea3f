// Tests of the Slurm job-array script: its #SBATCH lines from the sweep's resources,
// the array of a resumed sweep, and the quoting of every path (run by bash here; the
// round trip through a real Slurm is slurm_round_trip_test.cpp). docs/slurm.md.
#include "sweep/slurm_launcher.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/test_files.hpp"
#include "sweep/run_command.hpp"

namespace corrmp {
namespace {

using ::testing::HasSubstr;
using ::testing::StrEq;
using testing::TempDir;
using ::testing::ThrowsMessage;

Sweep a_sweep(int jobs) {
  Sweep sweep;
  sweep.id = "grid-20260101T000000Z-ab12";
  sweep.name = "grid";
  for (int i = 0; i < jobs; ++i) {
    SweepJob job;
    job.index = i;
    job.config_path = "configs/base.yaml";
    sweep.jobs.push_back(job);
  }
  return sweep;
}

SlurmPaths some_paths() {
  return {"/opt/corrmp/run_experiment", "/shared/sweep/manifest.json", "/shared/sweep/shards",
          "/shared/sweep/out", "/shared/sweep/logs"};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

bool has_line(const std::string& text, const std::string& line) {
  for (const std::string& l : lines_of(text)) {
    if (l == line) return true;
  }
  return false;
}

// Sets an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    had_ = std::getenv(name) != nullptr;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (had_) {
      ::setenv(name_, old_.c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::string old_;
  bool had_ = false;
};

TEST(SlurmArrayScript, OneArrayTaskPerJobWithTheSweepsResources) {
  Sweep sweep = a_sweep(5);
  sweep.slurm.cpus_per_task = 4;
  sweep.slurm.time = "02:30:00";
  sweep.slurm.memory = "8G";
  sweep.slurm.partition = "gpu";
  const std::string script = slurm_array_script(sweep, some_paths());
  EXPECT_EQ(lines_of(script).front(), "#!/bin/bash");
  EXPECT_TRUE(has_line(script, "#SBATCH --job-name=grid"));
  EXPECT_TRUE(has_line(script, "#SBATCH --array=0-4"));
  EXPECT_TRUE(has_line(script, "#SBATCH --cpus-per-task=4"));
  EXPECT_TRUE(has_line(script, "#SBATCH --time=02:30:00"));
  EXPECT_TRUE(has_line(script, "#SBATCH --mem=8G"));
  EXPECT_TRUE(has_line(script, "#SBATCH --partition=gpu"));
  EXPECT_TRUE(has_line(script, "#SBATCH --output=\"/shared/sweep/logs/job-%a.out\""));
  EXPECT_TRUE(has_line(script, "#SBATCH --error=\"/shared/sweep/logs/job-%a.err\""));
  EXPECT_TRUE(has_line(script, "set -euo pipefail"));
  EXPECT_TRUE(has_line(
      script,
      "exec '/opt/corrmp/run_experiment' --sweep-job '/shared/sweep/manifest.json' "
      "\"$SLURM_ARRAY_TASK_ID\" --db '/shared/sweep/shards'\"/job-$SLURM_ARRAY_TASK_ID.sqlite\" "
      "--out '/shared/sweep/out' --threads \"${SLURM_CPUS_PER_TASK:-1}\" --quiet"));
}

TEST(SlurmArrayScript, SbatchLinesComeBeforeTheFirstCommand) {
  // sbatch stops reading #SBATCH lines at the first command.
  const std::vector<std::string> lines = lines_of(slurm_array_script(a_sweep(2), some_paths()));
  bool command_seen = false;
  for (const std::string& line : lines) {
    if (line.rfind("#SBATCH", 0) == 0) {
      EXPECT_FALSE(command_seen) << line;
    } else if (!line.empty() && line[0] != '#') {
      command_seen = true;
    }
  }
  EXPECT_TRUE(command_seen);
}

TEST(SlurmArrayScript, LeavesThePartitionToTheClusterWhenUnset) {
  const std::string script = slurm_array_script(a_sweep(3), some_paths());
  EXPECT_EQ(script.find("--partition"), std::string::npos);
  EXPECT_TRUE(has_line(script, "#SBATCH --cpus-per-task=2"));
  EXPECT_TRUE(has_line(script, "#SBATCH --time=01:00:00"));
  EXPECT_TRUE(has_line(script, "#SBATCH --mem=4G"));
}

TEST(SlurmArrayScript, RunsOnlyTheSelectedJobsWithALimit) {
  SlurmArraySelection selection;
  selection.indices = {4, 1, 3};
  EXPECT_TRUE(
      has_line(slurm_array_script(a_sweep(6), some_paths(), selection), "#SBATCH --array=1,3-4"));
  selection.max_concurrent = 2;
  EXPECT_TRUE(
      has_line(slurm_array_script(a_sweep(6), some_paths(), selection), "#SBATCH --array=1,3-4%2"));
  selection.indices.clear();
  EXPECT_TRUE(
      has_line(slurm_array_script(a_sweep(6), some_paths(), selection), "#SBATCH --array=0-5%2"));
}

TEST(SlurmArraySpec, ConsecutiveIndicesBecomeRanges) {
  EXPECT_EQ(slurm_array_spec({0}), "0");
  EXPECT_EQ(slurm_array_spec({8, 7, 0, 1, 2, 5, 2}), "0-2,5,7-8");
  EXPECT_EQ(slurm_array_spec({3, 4}, 10), "3-4%10");
  EXPECT_THROW(slurm_array_spec({}), std::invalid_argument);
}

TEST(SlurmArrayScript, RefusesWhatAnArrayCannotRun) {
  EXPECT_THROW(slurm_array_script(a_sweep(0), some_paths()), std::invalid_argument);
  SlurmArraySelection outside;
  outside.indices = {1, 3};
  EXPECT_THROW(slurm_array_script(a_sweep(3), some_paths(), outside), std::invalid_argument);
  Sweep no_cpus = a_sweep(1);
  no_cpus.slurm.cpus_per_task = 0;
  EXPECT_THROW(slurm_array_script(no_cpus, some_paths()), std::invalid_argument);
}

TEST(SlurmArrayScript, RefusesResourcesAnSbatchLineCannotHold) {
  Sweep sweep = a_sweep(1);
  sweep.slurm.time = "1 hour";
  EXPECT_THAT([&] { slurm_array_script(sweep, some_paths()); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("slurm.time")));
  sweep.slurm.time = "1-00:00:00";
  sweep.slurm.partition = "a\nb";
  EXPECT_THROW(slurm_array_script(sweep, some_paths()), std::invalid_argument);
  sweep.slurm.partition = "short,long";
  EXPECT_TRUE(has_line(slurm_array_script(sweep, some_paths()), "#SBATCH --partition=short,long"));
}

TEST(SlurmArrayScript, RelativePathsBecomeAbsolute) {
  // The tasks run on other nodes, in sbatch's working directory.
  const SlurmPaths paths = {"bin/run_experiment", "sweep/./manifest.json", "sweep/shards",
                            "sweep/out", "sweep/logs"};
  const std::string here = std::filesystem::current_path().string();
  const std::string script = slurm_array_script(a_sweep(1), paths);
  EXPECT_TRUE(has_line(script, "#SBATCH --output=\"" + here + "/sweep/logs/job-%a.out\""));
  EXPECT_NE(script.find("exec '" + here + "/bin/run_experiment' --sweep-job '" + here +
                        "/sweep/manifest.json'"),
            std::string::npos)
      << script;
}

TEST(SlurmArrayScript, JobNameKeepsOnlyPlainCharacters) {
  Sweep sweep = a_sweep(1);
  sweep.name = "lr sweep/1";
  EXPECT_TRUE(has_line(slurm_array_script(sweep, some_paths()), "#SBATCH --job-name=lr_sweep_1"));
}

TEST(SlurmArrayScript, LogPatternsEscapeQuotesAndPercentSigns) {
  SlurmPaths paths = some_paths();
  paths.log_dir = "/shared/my \"best\" 100% logs";
  const std::string script = slurm_array_script(a_sweep(1), paths);
  EXPECT_TRUE(
      has_line(script, "#SBATCH --output=\"/shared/my \\\"best\\\" 100%% logs/job-%a.out\""));
  paths.log_dir = "/shared/back\\slash";
  EXPECT_THROW(slurm_array_script(a_sweep(1), paths), std::invalid_argument);
}

TEST(SlurmArrayScript, PathsWithSpacesAndQuotesReachTheProgramAsOneArgumentEach) {
  // The script's body run by bash as Slurm would run task 3 with 4 CPUs.
  TempDir dir;
  const std::string odd = dir.file("it's a \"dir\" $HOME `x`");
  const std::string recorder = dir.write("it's a \"dir\" $HOME `x`/run experiment",
                                         "#!/bin/bash\nprintf '%s\\n' \"$@\" > \"$(dirname "
                                         "\"$0\")/args\"\n");
  ASSERT_EQ(::chmod(recorder.c_str(), 0755), 0);
  const SlurmPaths paths = {recorder, odd + "/manifest.json", odd + "/shards", odd + "/out",
                            odd + "/logs"};
  const std::string script = dir.write("array.sbatch", slurm_array_script(a_sweep(4), paths));

  const ScopedEnv task("SLURM_ARRAY_TASK_ID", "3");
  const ScopedEnv cpus("SLURM_CPUS_PER_TASK", "4");
  const CommandResult ran = run_command({"bash", script});
  ASSERT_EQ(ran.exit_code, 0) << ran.err;

  std::ifstream args(odd + "/args");
  std::vector<std::string> recorded;
  for (std::string line; std::getline(args, line);) recorded.push_back(line);
  const std::vector<std::string> expected = {
      "--sweep-job", odd + "/manifest.json", "3",         "--db", odd + "/shards/job-3.sqlite",
      "--out",       odd + "/out",           "--threads", "4",    "--quiet"};
  EXPECT_EQ(recorded, expected);
}

TEST(SlurmArrayScript, ThreadsDefaultToOneOutsideSlurmsCpuRequest) {
  TempDir dir;
  const std::string recorder =
      dir.write("run", "#!/bin/bash\nprintf '%s\\n' \"$@\" > \"$(dirname \"$0\")/args\"\n");
  ASSERT_EQ(::chmod(recorder.c_str(), 0755), 0);
  const SlurmPaths paths = {recorder, "m", "s", "o", "l"};
  const std::string script = dir.write("array.sbatch", slurm_array_script(a_sweep(1), paths));
  const ScopedEnv task("SLURM_ARRAY_TASK_ID", "0");
  ::unsetenv("SLURM_CPUS_PER_TASK");
  ASSERT_EQ(run_command({"bash", script}).exit_code, 0);
  std::ifstream args(dir.file("args"));
  std::string all((std::istreambuf_iterator<char>(args)), std::istreambuf_iterator<char>());
  EXPECT_NE(all.find("--threads\n1\n"), std::string::npos) << all;
}

TEST(SlurmSubmit, SaysHowToWriteTheFilesOnlyWhenSbatchIsMissing) {
  TempDir dir;
  const ScopedEnv path("PATH", dir.path().string());  // an empty directory: no sbatch
  EXPECT_THAT(
      [&] { submit_slurm(dir.write("array.sbatch", "#!/bin/bash\n"), false); },
      ThrowsMessage<std::runtime_error>(StrEq(
          "sbatch not found: is Slurm installed? use --emit slurm DIR to only write the files")));
}

TEST(RunCommand, CapturesBothOutputsAndTheExitStatus) {
  const CommandResult result =
      run_command({"bash", "-c", "printf out; printf err >&2; exit 7", "ignored"});
  EXPECT_EQ(result.out, "out");
  EXPECT_EQ(result.err, "err");
  EXPECT_EQ(result.exit_code, 7);
  EXPECT_EQ(run_command({"bash", "-c", "kill -TERM $$"}).exit_code, 128 + 15);
  EXPECT_THROW(run_command({"/nonexistent/program"}), CommandNotFound);
}

TEST(RunCommand, ReadsLargeOutputsOnBothStreams) {
  // More than a pipe holds on each stream: reading one while the program blocks on the
  // other would never finish.
  const CommandResult result = run_command(
      {"bash", "-c", "head -c 300000 /dev/zero; head -c 300000 /dev/zero >&2; echo done"});
  EXPECT_EQ(result.out.size(), 300005u);
  EXPECT_EQ(result.err.size(), 300000u);
  EXPECT_EQ(result.exit_code, 0);
}

}  // namespace
}  // namespace corrmp
