// Tests of core/file_read.hpp: each kind of unreadable path gives one line
// naming it and saying what it is, and a named pipe does not hang the reader.
#include "core/file_read.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "config/test_files.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

std::string error_of(const std::string& path) {
  try {
    read_whole_file(path);
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), path);
    return e.what();
  }
  return "";
}

TEST(FileRead, ReadsEveryByte) {
  TempDir dir;
  const std::string bytes("a\0b\xff\n", 5);
  const std::string path = dir.write("f.bin", bytes);
  EXPECT_EQ(read_whole_file(path), bytes);
  EXPECT_EQ(read_whole_file(dir.write("empty", "")), "");
}

TEST(FileRead, EachUnreadablePathIsNamedWithWhatItIs) {
  TempDir dir;
  std::filesystem::create_directories(dir.file("cache.bin"));
  EXPECT_EQ(error_of(dir.file("cache.bin")), dir.file("cache.bin") + ": is a directory");
  EXPECT_EQ(error_of(dir.file("missing")),
            dir.file("missing") + ": cannot open for reading: No such file or directory");
  EXPECT_EQ(error_of("/dev/null"), "/dev/null: is not a regular file (a character device)");
  const std::string pipe = dir.file("pipe");
  ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
  EXPECT_EQ(error_of(pipe), pipe + ": is not a regular file (a named pipe)");
}

}  // namespace
}  // namespace corrmp
