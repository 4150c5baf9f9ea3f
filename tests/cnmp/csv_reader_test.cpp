// Tests of cnmp/csv_reader.hpp: parsing one-demonstration-per-file CSV trajectories (header row,
// then one row per time step), tolerated formatting variations, the one-line "path:line: ..."
// DataError for every kind of bad file, and the same-columns check across files.
#include "cnmp/csv_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace corrmp {
namespace {

namespace fs = std::filesystem;

class CsvReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static int counter = 0;
    dir_ = fs::temp_directory_path() / ("corrmp-csv-reader-test-" + std::to_string(::getpid()) +
                                        "-" + std::to_string(counter++));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  // The DataError message of `body`; checks it is one line starting with `prefix`.
  static std::string error_of(const std::function<void()>& body, const std::string& prefix) {
    try {
      body();
    } catch (const DataError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      return message;
    }
    ADD_FAILURE() << "no DataError";
    return "";
  }

  // The message of reading the CSV file `name` with contents `text`.
  std::string csv_error(const std::string& name, const std::string& text, int line) {
    const std::string path = write(name, text);
    return error_of([&] { read_csv_trajectory(path); }, path + ":" + std::to_string(line) + ": ");
  }

  fs::path dir_;
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST_F(CsvReaderTest, ParsesHeaderAndRows) {
  const std::string path = write("demo.csv", "t,x,y\n0,1.5,-2\n0.5,2e-1,+3.25\n1,-1E2,0\n");
  const RawTrajectory trajectory = read_csv_trajectory(path);
  EXPECT_EQ(trajectory.source, path);
  EXPECT_EQ(trajectory.columns, (std::vector<std::string>{"t", "x", "y"}));
  ASSERT_EQ(trajectory.values.rows(), 3);
  ASSERT_EQ(trajectory.values.cols(), 3);
  Eigen::MatrixXd expected(3, 3);
  expected << 0, 1.5, -2, 0.5, 0.2, 3.25, 1, -100, 0;
  EXPECT_EQ(trajectory.values, expected);
}

TEST_F(CsvReaderTest, ToleratesSpacesCrLfBlankLinesAndMissingFinalNewline) {
  const std::string path = write(
      "demo.csv", "\r\n  time , joint 1 ,\tgrip\r\n 0 , 1 ,\t2 \r\n\r\n\n 1,  3,4\r\n  \r\n2,5,6");
  const RawTrajectory trajectory = read_csv_trajectory(path);
  EXPECT_EQ(trajectory.columns, (std::vector<std::string>{"time", "joint 1", "grip"}));
  Eigen::MatrixXd expected(3, 3);
  expected << 0, 1, 2, 1, 3, 4, 2, 5, 6;
  EXPECT_EQ(trajectory.values, expected);
}

TEST_F(CsvReaderTest, ReadsSingleColumnWithUtf8ByteOrderMark) {
  const std::string path = write("one.csv", "\xEF\xBB\xBFy\n0.25\n0.75\n");
  const RawTrajectory trajectory = read_csv_trajectory(path);
  EXPECT_EQ(trajectory.columns, (std::vector<std::string>{"y"}));
  ASSERT_EQ(trajectory.values.rows(), 2);
  EXPECT_EQ(trajectory.values(1, 0), 0.75);
}

TEST_F(CsvReaderTest, MissingFileIsAnError) {
  const std::string path = (dir_ / "absent.csv").string();
  EXPECT_EQ(error_of([&] { read_csv_trajectory(path); }, path + ": "), path + ": no such file");
}

TEST_F(CsvReaderTest, EmptyFileIsAnError) {
  EXPECT_TRUE(contains(csv_error("empty.csv", "", 1), "empty file: expected a header row"));
  EXPECT_TRUE(contains(csv_error("blank.csv", "\n \r\n\n", 1), "empty file"));
}

TEST_F(CsvReaderTest, NumericFirstLineIsReportedAsMissingHeader) {
  EXPECT_TRUE(contains(csv_error("nohead.csv", "\n0.1, 2\n0.2, 3\n", 2),
                       "no header row: the first line '0.1, 2' holds only numbers"));
}

TEST_F(CsvReaderTest, EmptyColumnNamesAreErrors) {
  EXPECT_TRUE(contains(csv_error("gap.csv", "t,,y\n1,2,3\n", 1),
                       "empty column name in the header (column 2 of 3)"));
  EXPECT_TRUE(contains(csv_error("trail.csv", "t,y,\n1,2,3\n", 1),
                       "empty column name in the header (column 3 of 3)"));
}

TEST_F(CsvReaderTest, DuplicateColumnNamesAreErrors) {
  EXPECT_TRUE(contains(csv_error("dup.csv", "x, y , x\n1,2,3\n", 1),
                       "duplicate column name 'x' in the header (columns 1 and 3)"));
}

TEST_F(CsvReaderTest, RaggedRowsReportExpectedAndActualFieldCounts) {
  EXPECT_TRUE(contains(csv_error("short.csv", "t,x,y\n0,1,2\r\n1,2\r\n", 3),
                       "ragged row: expected 3 fields (as in the header), got 2"));
  EXPECT_TRUE(contains(csv_error("long.csv", "t,x\n\n0,1,2\n", 3),
                       "ragged row: expected 2 fields (as in the header), got 3"));
}

TEST_F(CsvReaderTest, NonNumericFieldsAreQuoted) {
  EXPECT_TRUE(contains(csv_error("text.csv", "t,x\n0,1\n1, abc \n", 3),
                       "field 2 (column 'x') is not a number: \"abc\""));
  EXPECT_TRUE(contains(csv_error("blankfield.csv", "t,x\n0,\n", 2),
                       "field 2 (column 'x') is not a number: \"\""));
  EXPECT_TRUE(contains(csv_error("suffix.csv", "t,x\n0,1.5m\n", 2), "is not a number: \"1.5m\""));
  EXPECT_TRUE(contains(csv_error("signs.csv", "t,x\n+-1,0\n", 2),
                       "field 1 (column 't') is not a number: \"+-1\""));
  EXPECT_TRUE(contains(csv_error("hex.csv", "t,x\n0x10,0\n", 2), "is not a number: \"0x10\""));
}

TEST_F(CsvReaderTest, NonFiniteValuesAreErrors) {
  EXPECT_TRUE(contains(csv_error("nan.csv", "t,x\n0,1\n1,nan\n", 3),
                       "non-finite value \"nan\" in column 'x'"));
  EXPECT_TRUE(contains(csv_error("inf.csv", "t,x\n-inf,1\n", 2),
                       "non-finite value \"-inf\" in column 't'"));
  EXPECT_TRUE(contains(csv_error("NaN.csv", "t,x\n0,NaN\n", 2), "non-finite value \"NaN\""));
  EXPECT_TRUE(contains(csv_error("huge.csv", "t,x\n0,1e999\n", 2),
                       "value \"1e999\" in column 'x' is out of the range of a double"));
}

TEST_F(CsvReaderTest, HeaderWithoutDataRowsIsAnError) {
  EXPECT_TRUE(contains(csv_error("head.csv", "t,x\n", 1), "no data rows after the header"));
  EXPECT_TRUE(contains(csv_error("head3.csv", "\r\n\r\nt,x\r\n\r\n", 3), "no data rows"));
}

TEST_F(CsvReaderTest, ReadsSeveralFilesWithTheSameColumns) {
  const std::string a = write("a.csv", "t,x\n0,1\n1,2\n");
  const std::string b = write("b.csv", "t , x\n0,5\n");
  const auto trajectories = read_csv_trajectories({a, b});
  ASSERT_EQ(trajectories.size(), 2u);
  EXPECT_EQ(trajectories[0].source, a);
  EXPECT_EQ(trajectories[1].source, b);
  EXPECT_EQ(trajectories[0].values.rows(), 2);
  EXPECT_EQ(trajectories[1].values.rows(), 1);
  EXPECT_EQ(trajectories[1].values(0, 1), 5.0);
  EXPECT_TRUE(read_csv_trajectories({}).empty());
}

TEST_F(CsvReaderTest, DifferentColumnsAcrossFilesNameBothFiles) {
  const std::string a = write("a.csv", "t,x,y\n0,1,2\n");
  const std::string b = write("b.csv", "t,x,y\n0,1,2\n");
  const std::string swapped = write("c.csv", "\nt,y,x\n0,1,2\n");
  EXPECT_EQ(error_of(
                [&] {
                  read_csv_trajectories({a, b, swapped});
                },
                swapped + ":2: "),
            swapped + ":2: columns [t, y, x] differ from the columns [t, x, y] of " + a);
  const std::string fewer = write("d.csv", "t,x\n0,1\n");
  EXPECT_TRUE(contains(error_of(
                           [&] {
                             read_csv_trajectories({a, fewer});
                           },
                           fewer + ":1: "),
                       "columns [t, x] differ from the columns [t, x, y] of " + a));
}

TEST_F(CsvReaderTest, ErrorInLaterFileNamesThatFile) {
  const std::string a = write("a.csv", "t,x\n0,1\n");
  const std::string bad = write("bad.csv", "t,x\n0,oops\n");
  EXPECT_TRUE(contains(error_of(
                           [&] {
                             read_csv_trajectories({a, bad});
                           },
                           bad + ":2: "),
                       "\"oops\""));
}

}  // namespace
}  // namespace corrmp
