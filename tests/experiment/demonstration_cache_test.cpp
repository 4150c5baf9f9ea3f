// Tests of the demonstration cache: exact round trips and corrupt files.
#include "experiment/demonstration_cache.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "config/test_files.hpp"

namespace corrmp {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

Demonstration cached_demonstration(double value) {
  SegmentTrajectory s;
  s.segment = "cor";
  s.x = Eigen::MatrixXd::Random(5, 1);
  s.y = Eigen::MatrixXd::Random(5, 3) * value;
  s.context = Eigen::VectorXd::Constant(1, 1.0 / 3.0);
  s.phase_begin = 0.1 * value;
  s.phase_end = 1.0 / 3.0;
  s.start.state = {{"corridor_x", 0.4512345678901234}, {"object_x", value}};
  s.start.rgb = cv::Mat(4, 6, CV_8UC3, cv::Scalar(10, 200, 30));
  s.start.depth = cv::Mat(4, 6, CV_32FC1, cv::Scalar(0.612345f));
  return Demonstration{"{\"corridor_offset\":0.01}", {s}, "push"};
}

TEST(DemonstrationCache, RoundTripsExactly) {
  testing::TempDir dir;
  DemonstrationSplit demos;
  demos.train = {cached_demonstration(1.0), cached_demonstration(2.0)};
  demos.validation = {cached_demonstration(3.0)};
  demos.validation[0].segments[0].start.rgb = cv::Mat();
  const std::string path = dir.file("cache/d.bin");
  save_demonstrations(path, demos);
  const auto loaded = load_demonstrations(path);
  ASSERT_TRUE(loaded.has_value());
  ASSERT_EQ(loaded->train.size(), 2u);
  ASSERT_EQ(loaded->validation.size(), 1u);
  const auto& a = demos.train[1].segments[0];
  const auto& b = loaded->train[1].segments[0];
  EXPECT_EQ(loaded->train[1].scenario, demos.train[1].scenario);
  EXPECT_EQ(loaded->train[1].decision, "push");
  EXPECT_EQ(b.segment, "cor");
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.context, b.context);
  EXPECT_EQ(a.phase_begin, b.phase_begin);
  EXPECT_EQ(a.phase_end, b.phase_end);
  EXPECT_EQ(a.start.state, b.start.state);
  EXPECT_EQ(cv::norm(a.start.rgb, b.start.rgb, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.start.depth, b.start.depth, cv::NORM_INF), 0.0);
  EXPECT_TRUE(loaded->validation[0].segments[0].start.rgb.empty());
  EXPECT_FALSE(load_demonstrations(dir.file("missing.bin")).has_value());
}

TEST(DemonstrationCache, CorruptFilesAreReportedWithTheirName) {
  testing::TempDir dir;
  DemonstrationSplit demos;
  demos.train = {cached_demonstration(1.0)};
  const std::string path = dir.file("d.bin");
  save_demonstrations(path, demos);
  {
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(40);
    file.put('\x7f');
  }
  EXPECT_THAT([&] { load_demonstrations(path); },
              ThrowsMessage<std::runtime_error>(AllOf(HasSubstr(path), HasSubstr("checksum"))));
  std::ofstream(dir.file("junk.bin")) << "not a cache at all";
  EXPECT_THROW(load_demonstrations(dir.file("junk.bin")), std::runtime_error);
}

}  // namespace
}  // namespace corrmp
