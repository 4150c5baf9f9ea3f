// Tests that the demonstration file readers (npy_reader, csv_reader and the
// trajectory_files paths through them) name a path that is not a regular
// file and say what it is, instead of hanging on a pipe or reading a device.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "cnmp/csv_reader.hpp"
#include "cnmp/npy_reader.hpp"
#include "cnmp/trajectory_dataset.hpp"
#include "config/test_files.hpp"

namespace corrmp {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

template <class Body>
std::string data_error_of(Body body) {
  try {
    body();
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

TEST(SpecialFiles, ANamedPipeIsNamedNotWaitedOn) {
  TempDir dir;
  const std::string npy = dir.file("demos.npy"), csv = dir.file("demo.csv");
  ASSERT_EQ(mkfifo(npy.c_str(), 0600), 0);
  ASSERT_EQ(mkfifo(csv.c_str(), 0600), 0);
  EXPECT_EQ(data_error_of([&] { read_npy_trajectories(npy); }),
            npy + ": is not a regular file (a named pipe)");
  EXPECT_EQ(data_error_of([&] { read_csv_trajectory(csv); }),
            csv + ": is not a regular file (a named pipe)");
  EXPECT_EQ(data_error_of([&] { read_trajectory_files({npy}); }),
            npy + ": is not a regular file (a named pipe)");
}

TEST(SpecialFiles, ALinkToADeviceIsNamed) {
  TempDir dir;
  const std::string npy = dir.file("null.npy"), csv = dir.file("null.csv");
  fs::create_symlink("/dev/null", npy);
  fs::create_symlink("/dev/null", csv);
  EXPECT_EQ(data_error_of([&] { read_npy_trajectories(npy); }),
            npy + ": is not a regular file (a character device)");
  EXPECT_EQ(data_error_of([&] { read_csv_trajectory(csv); }),
            csv + ": is not a regular file (a character device)");
}

TEST(SpecialFiles, ADirectoryIsNamed) {
  TempDir dir;
  fs::create_directories(dir.file("a.npy"));
  fs::create_directories(dir.file("a.csv"));
  EXPECT_EQ(data_error_of([&] { read_npy_trajectories(dir.file("a.npy")); }),
            dir.file("a.npy") + ": is a directory, expected a .npy file");
  EXPECT_EQ(data_error_of([&] { read_csv_trajectory(dir.file("a.csv")); }),
            dir.file("a.csv") + ": is a directory, expected a CSV file");
}

}  // namespace
}  // namespace corrmp
