// Tests of core/atomic_file.hpp: a failed write (file size limit, missing
// folder, a directory in the way) leaves the old file as it was and no
// temporary file; leftovers of killed writers are never read and are removed.
#include "core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/test_files.hpp"
#include "file_size_limit.hpp"

namespace corrmp {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::vector<std::string> names_in(const TempDir& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string host() {
  char buffer[256] = {};
  gethostname(buffer, sizeof buffer - 1);
  return buffer;
}

// The id of a process that has ended (a child that exited and was reaped).
pid_t ended_process() {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  return child;
}

// The problem of the FileError `body` throws, checking that it names `path`.
template <class Body>
std::string problem_of(Body body, const std::string& path) {
  try {
    body();
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), path);
    EXPECT_EQ(std::string(e.what()), path + ": " + e.problem());
    return e.problem();
  }
  ADD_FAILURE() << "no FileError for " << path;
  return "";
}

TEST(AtomicFile, WritesAndReplacesLeavingNoTemporaryFile) {
  TempDir dir;
  const std::string path = dir.file("model.bin");
  write_file_atomically(path, "first");
  write_file_atomically(path, "second, longer");
  EXPECT_EQ(contents(path), "second, longer");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"model.bin"});
}

TEST(AtomicFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  TempDir dir;
  const std::string path = dir.file("cache.bin");
  write_file_atomically(path, "good");
  const std::string big(1 << 16, 'x');
  std::string problem;
  {
    testing::FileSizeLimit limit(1000);
    problem = problem_of([&] { write_file_atomically(path, big); }, path);
  }
  EXPECT_NE(problem.find("cannot write: File too large"), std::string::npos) << problem;
  EXPECT_EQ(contents(path), "good");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"cache.bin"});
}

TEST(AtomicFile, AMissingFolderOrADirectoryInTheWayIsNamed) {
  TempDir dir;
  const std::string missing = dir.file("no/such/folder/f.bin");
  EXPECT_EQ(problem_of([&] { write_file_atomically(missing, "x"); }, missing),
            "cannot write: its folder does not exist");
  const std::string folder = dir.file("a_directory");
  fs::create_directories(folder + "/inside");
  EXPECT_EQ(problem_of([&] { write_file_atomically(folder, "x"); }, folder), "is a directory");
  EXPECT_TRUE(fs::is_directory(folder + "/inside"));
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"a_directory"});
}

TEST(AtomicFile, TemporaryNamesAreTheWritersOwn) {
  EXPECT_TRUE(is_temporary_name("m.cmpm.tmp.node-1.example.org.123.0", "m.cmpm"));
  EXPECT_TRUE(is_temporary_name("m.cmpm.tmp.h.1.42", "m.cmpm"));
  EXPECT_FALSE(is_temporary_name("m.cmpm", "m.cmpm"));
  EXPECT_FALSE(is_temporary_name("m.cmpm.tmp", "m.cmpm"));
  EXPECT_FALSE(is_temporary_name("m.cmpm.tmp.h.x.1", "m.cmpm"));
  EXPECT_FALSE(is_temporary_name("m.cmpm.lock", "m.cmpm"));
  EXPECT_FALSE(is_temporary_name("other.cmpm.tmp.h.1.1", "m.cmpm"));
}

// A killed writer's temporary file is not the file: the next write removes it
// when its process has ended on this host, and keeps those that may be alive.
TEST(AtomicFile, LeftoversOfEndedWritersOnThisHostAreRemoved) {
  TempDir dir;
  const std::string path = dir.file("d.bin");
  const std::string ended = std::to_string(ended_process());
  const std::string stale = "d.bin.tmp." + host() + "." + ended + ".0";
  const std::string alive = "d.bin.tmp." + host() + "." + std::to_string(getppid()) + ".3";
  const std::string elsewhere = "d.bin.tmp.some-other-host." + ended + ".0";
  const std::string unrelated = "e.bin.tmp." + host() + "." + ended + ".0";
  for (const auto& name : {stale, alive, elsewhere, unrelated}) dir.write(name, "half a fi");
  write_file_atomically(path, "whole");
  EXPECT_EQ(contents(path), "whole");
  std::vector<std::string> kept{"d.bin", alive, elsewhere, unrelated};
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(names_in(dir), kept);
}

}  // namespace
}  // namespace corrmp
