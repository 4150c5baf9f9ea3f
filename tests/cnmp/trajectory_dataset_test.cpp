// Tests of choosing CNMP columns from researchers' trajectory files.
#include "cnmp/trajectory_dataset.hpp"

#include <gtest/gtest.h>

#include "config/test_files.hpp"

namespace corrmp {
namespace {

using testing::TempDir;

std::string message_of(const std::function<void()>& body) {
  try {
    body();
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

TEST(TrajectoryDataset, SelectsColumnsAndNormalisesTime) {
  TempDir dir;
  dir.write("demos/a.csv", "t,x,y,c\n2,0,1,5\n3,1,2,5\n4,2,4,5\n");
  dir.write("demos/b.csv", "t,x,y,c\n0,0,0,7\n1,1,1,7\n");
  dir.write("demos/notes.txt", "ignored");
  const auto raw = read_trajectory_files({dir.file("demos")});
  ASSERT_EQ(raw.size(), 2u);
  const auto data = select_columns(raw, {"t", {"x"}, {"y"}, {"c"}});
  ASSERT_EQ(data.size(), 2u);
  EXPECT_EQ(data[0].x.col(0).transpose(), Eigen::RowVector3d(0.0, 0.5, 1.0));
  EXPECT_EQ(data[0].x.col(1).transpose(), Eigen::RowVector3d(0.0, 1.0, 2.0));
  EXPECT_EQ(data[0].y.col(0).transpose(), Eigen::RowVector3d(1.0, 2.0, 4.0));
  EXPECT_EQ(data[1].context[0], 7.0);
  const auto by_index = select_columns(raw, {"", {}, {"y", "x"}, {}});
  EXPECT_EQ(by_index[1].x.col(0).transpose(), Eigen::RowVector2d(0.0, 1.0));
  EXPECT_EQ(by_index[0].y.cols(), 2);
  EXPECT_EQ(by_index[0].context.size(), 0);
}

TEST(TrajectoryDataset, ReportsBadColumnsAndPaths) {
  TempDir dir;
  const auto file = dir.write("a.csv", "t,y,c\n0,1,5\n1,2,6\n1,3,5\n");
  const auto raw = read_trajectory_files({file});
  EXPECT_NE(message_of([&] {
              select_columns(raw, {"", {}, {"z"}, {}});
            }).find("no column 'z' (columns: t, y, c)"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              select_columns(raw, {"t", {}, {"y"}, {}});
            }).find("time column 't' does not increase at step 2"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              select_columns(raw, {"", {}, {"y"}, {"c"}});
            }).find("context column 'c' varies"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              read_trajectory_files({dir.file("missing")});
            }).find("no such file or directory"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              read_trajectory_files({dir.write("x.txt", "1")});
            }).find("expected a .npy or .csv file"),
            std::string::npos);
}

}  // namespace
}  // namespace corrmp
