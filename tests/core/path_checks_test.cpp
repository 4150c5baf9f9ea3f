// Checks on paths before they are written (core/path_checks.hpp): the same file under other
// spellings and through a link, and the file in the way of a folder.
#include "core/path_checks.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "config/test_files.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

TEST(PathChecks, SameFileFollowsSpellingsAndLinks) {
  TempDir dir;
  const std::string file = dir.write("a.csv", "t\n0\n");
  dir.write("b.csv", "t\n0\n");
  std::filesystem::create_directories(dir.file("sub"));
  std::filesystem::create_symlink(file, dir.file("link.csv"));
  EXPECT_TRUE(same_file(file, dir.file("./a.csv")));
  EXPECT_TRUE(same_file(file, dir.file("sub/../a.csv")));
  EXPECT_TRUE(same_file(file, dir.file("link.csv")));
  EXPECT_FALSE(same_file(file, dir.file("b.csv")));  // the same bytes, another file
  EXPECT_FALSE(same_file(file, dir.file("missing.csv")));
}

TEST(PathChecks, NamesTheFileInTheWayOfAFolder) {
  TempDir dir;
  const std::string file = dir.write("afile", "x\n");
  EXPECT_EQ(file_in_the_way(file), "'" + file + "' is a file, not a folder");
  EXPECT_EQ(file_in_the_way(file + "/below/deeper"), "'" + file + "' is a file, not a folder");
  EXPECT_EQ(file_in_the_way(dir.file("new/folder")), "");
  EXPECT_EQ(file_in_the_way(dir.path().string()), "");
}

}  // namespace
}  // namespace corrmp
