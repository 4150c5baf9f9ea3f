// Writing and submitting a sweep's Slurm files (docs/slurm.md): a folder that cannot hold them
// is refused in one line before anything is written, and a submission sbatch refuses leaves
// nothing of this invocation behind. The failing sbatch here is a stand-in on the PATH: what is
// tested is the cleanup after any refusal (the real Slurm is sweep_command_test.cpp's).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "config/test_files.hpp"
#include "sweep/sweep_command_support.hpp"

namespace corrmp {
namespace {

using testing::kTiny;
using testing::line_count;
using testing::Outcome;
using testing::run;
using testing::TempDir;

// Puts a folder first on this process's PATH (and its children's) for one scope.
class FirstOnPath {
 public:
  explicit FirstOnPath(const std::string& folder) {
    if (const char* path = std::getenv("PATH")) old_ = path;
    ::setenv("PATH", (folder + ":" + old_).c_str(), 1);
  }
  ~FirstOnPath() { ::setenv("PATH", old_.c_str(), 1); }
  FirstOnPath(const FirstOnPath&) = delete;
  FirstOnPath& operator=(const FirstOnPath&) = delete;

 private:
  std::string old_;
};

TEST(SweepSubmission, EmitRefusesAnEmptyFolderWithoutRunningAnything) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const Outcome outcome = run(dir, config + " -m seed=0,1 --emit slurm ''");
  EXPECT_EQ(outcome.exit_code, 2) << outcome.out;
  EXPECT_EQ(outcome.out, "run_experiment: --emit slurm: the folder is empty\n");
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("runs")));
}

TEST(SweepSubmission, EmitIntoAFolderThatCannotBeMadeNamesItInOneLine) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const std::string file = dir.write("file", "x\n");
  for (const std::string& folder : {file, file + "/sub", std::string("/proc/x")}) {
    const Outcome outcome = run(dir, config + " -m seed=0,1 --emit slurm " + folder);
    EXPECT_EQ(outcome.exit_code, 2) << folder << ": " << outcome.out;
    EXPECT_EQ(outcome.out.rfind("--emit slurm: cannot make the folder " + folder + ": ", 0), 0u)
        << outcome.out;
    EXPECT_EQ(line_count(outcome.out), 1) << outcome.out;
    EXPECT_FALSE(std::filesystem::exists(dir.file("runs")));
  }
  EXPECT_EQ(testing::read_text(file), "x\n");
}

TEST(SweepSubmission, ARefusedSubmissionLeavesNothingOfThisInvocationBehind) {
  TempDir dir;
  const std::string config = dir.write("tiny.yaml", kTiny);
  const std::string sbatch = dir.write(
      "bin/sbatch", "#!/bin/sh\necho 'sbatch: error: Batch job submission failed' >&2\nexit 1\n");
  ASSERT_EQ(::chmod(sbatch.c_str(), 0755), 0);
  const FirstOnPath fake_sbatch(dir.file("bin"));
  // --out made by this invocation: removed with everything in it.
  const Outcome fresh = run(dir, config + " -m seed=0,1 --launcher slurm");
  EXPECT_EQ(fresh.exit_code, 1) << fresh.out;
  EXPECT_NE(fresh.out.find("sbatch could not submit"), std::string::npos) << fresh.out;
  EXPECT_NE(fresh.out.find("Batch job submission failed"), std::string::npos) << fresh.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("runs")));
  // An --out that was there keeps what it held, and only that.
  const std::string kept = dir.write("runs/sweeps/other/keep.txt", "kept\n");
  const Outcome existing = run(dir, config + " -m seed=0,1 --launcher slurm");
  EXPECT_EQ(existing.exit_code, 1) << existing.out;
  EXPECT_TRUE(std::filesystem::exists(kept));
  int left = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir.file("runs"))) {
    ++left;
    (void)entry;
  }
  EXPECT_EQ(left, 3);  // sweeps, sweeps/other, sweeps/other/keep.txt
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));
}

}  // namespace
}  // namespace corrmp
