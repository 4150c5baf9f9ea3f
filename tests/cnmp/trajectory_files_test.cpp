// Tests of the trajectory_files demonstration source: the files are read and
// checked once, when the source is made (a bad file is refused then, naming
// the file and line), and the run's demonstrations are what was read.
#include "cnmp/trajectory_files.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "config/test_files.hpp"
#include "core/parameter_error.hpp"

namespace corrmp {
namespace {

using ::testing::StrEq;
using testing::TempDir;
using ::testing::ThrowsMessage;

TrajectoryFilesParams params_for(const std::string& path, const std::string& output) {
  TrajectoryFilesParams params;
  params.paths = {path};
  params.time_column = "t";
  params.output_columns = {output};
  return params;
}

// The key and message of the ParameterError `body` throws ("" when none).
std::pair<std::string, std::string> parameter_error_of(const std::function<void()>& body) {
  try {
    body();
  } catch (const ParameterError& e) {
    return {e.key(), e.what()};
  }
  return {};
}

TEST(TrajectoryFiles, BadContentsAreRefusedWhenLoadedNamingTheFileAndLine) {
  TempDir dir;
  const std::string ragged = dir.write("ragged.csv", "t,x\n0,0\n1,0.5,7\n");
  EXPECT_EQ(parameter_error_of([&] { load_trajectory_files(params_for(ragged, "x")); }),
            std::make_pair(std::string("paths"),
                           ragged + ":3: ragged row: expected 2 fields (as in the header), got 3"));
  const std::string nan = dir.write("nan.csv", "t,x\n0,0\n1,nan\n");
  EXPECT_EQ(
      parameter_error_of([&] { load_trajectory_files(params_for(nan, "x")); }),
      std::make_pair(std::string("paths"), nan + ":3: non-finite value \"nan\" in column 'x'"));
  const std::string good = dir.write("good.csv", "t,x\n0,0\n1,0.5\n");
  EXPECT_THAT(
      [&] { load_trajectory_files(params_for(good, "y")); },
      ThrowsMessage<std::invalid_argument>(StrEq(good + ": no column 'y' (columns: t, x)")));
  EXPECT_EQ(parameter_error_of([&] { load_trajectory_files(params_for(good, "x")); }).first, "");
  TrajectoryFilesParams none = params_for(good, "x");
  none.paths.clear();
  EXPECT_EQ(parameter_error_of([&] { load_trajectory_files(none); }),
            std::make_pair(std::string("paths"), std::string("no demonstration files given")));
}

TEST(TrajectoryFiles, TheDemonstrationsAreWhatWasReadAtLoad) {
  TempDir dir;
  for (int i = 0; i < 5; ++i) {
    dir.write("demos/" + std::to_string(i) + ".csv",
              "t,x\n0," + std::to_string(i) + "\n2," + std::to_string(10 + i) + "\n");
  }
  const TrajectoryFilesParams params = params_for(dir.file("demos"), "x");
  TrajectoryFiles source(params, load_trajectory_files(params));
  std::filesystem::remove_all(dir.file("demos"));  // read once: no longer needed
  Rng rng = SeedTree(1).stream("demonstrations");
  const DemonstrationSplit split = source.collect(nullptr, rng);
  ASSERT_EQ(split.validation.size(), 1u);  // floor(0.2 * 5)
  ASSERT_EQ(split.train.size(), 4u);
  std::set<double> starts;
  for (const auto* set : {&split.train, &split.validation}) {
    for (const Demonstration& demo : *set) {
      ASSERT_EQ(demo.segments.size(), 1u);
      const SegmentTrajectory& segment = demo.segments[0];
      EXPECT_EQ(segment.segment, "full");
      EXPECT_EQ(segment.x.col(0).transpose(), Eigen::RowVector2d(0.0, 1.0));
      const double first = segment.y(0, 0);
      EXPECT_EQ(segment.y(1, 0), first + 10);
      const std::string file =
          dir.file("demos/" + std::to_string(static_cast<int>(first)) + ".csv");
      EXPECT_NE(demo.scenario.find(file), std::string::npos) << demo.scenario;
      starts.insert(first);
    }
  }
  EXPECT_EQ(starts, (std::set<double>{0, 1, 2, 3, 4}));
}

}  // namespace
}  // namespace corrmp
