// Tests of the evaluation's trajectory outputs: the CSV's exact content and
// the figure's layout, colours (the executed path's dashes) and errors.
#include "evaluation/trajectory_outputs.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "config/test_files.hpp"

namespace corrmp {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using ::testing::ThrowsMessage;

TaskReport xyz_task() {
  TaskReport task;
  task.trajectory_columns = {"x", "y", "z"};
  task.plot_horizontal = 1;
  task.plot_vertical = 0;
  return task;
}

EvaluatedTrial a_trial(int index, bool success) {
  EvaluatedTrial trial;
  trial.trial = index;
  trial.success = success;
  trial.expected_action = "push";
  trial.chosen_action = "pull";
  Eigen::MatrixXd expert(2, 3), generated(2, 3);
  expert << 0.40, -0.20, 0.03, 0.40, 0.00, 0.03;  // along y at x = 0.40
  generated << 0.42, -0.20, 0.03, 0.42, 0.00, 0.03;
  trial.expert["cor"] = expert;
  trial.generated["cor"] = generated;
  return trial;
}

TEST(TrajectoryOutputs, CsvHoldsEveryGeneratedExpertAndExecutedPoint) {
  TempDir dir;
  EvaluatedTrial relative = a_trial(3, false);
  Eigen::RowVectorXd origin(3);
  origin << 1, 2, 3;
  relative.origins["cor"] = origin;
  Eigen::MatrixXd stopped(1, 3);  // executed its first row only, 1 cm short in x
  stopped << 0.41, -0.2, 0.03;
  relative.executed["cor"] = stopped;
  EvaluatedTrial executed = a_trial(0, true);
  executed.executed["cor"] = executed.generated["cor"];
  write_trajectory_csv({executed, relative, a_trial(5, true)}, xyz_task(), dir.file("t.csv"));
  std::stringstream text;
  text << std::ifstream(dir.file("t.csv")).rdbuf();
  // The relative segment (offsets from (1, 2, 3)) is written in world coordinates; rows
  // not executed, and trials without an executed path, have empty executed fields.
  EXPECT_EQ(text.str(),
            "trial,segment,step,x,y,z,expert_x,expert_y,expert_z,executed_x,executed_y,"
            "executed_z\n"
            "0,cor,0,0.42,-0.2,0.03,0.4,-0.2,0.03,0.42,-0.2,0.03\n"
            "0,cor,1,0.42,0,0.03,0.4,0,0.03,0.42,0,0.03\n"
            "3,cor,0,1.42,1.8,3.03,1.4,1.8,3.03,1.41,1.8,3.03\n"
            "3,cor,1,1.42,2,3.03,1.4,2,3.03,,,\n"
            "5,cor,0,0.42,-0.2,0.03,0.4,-0.2,0.03,,,\n"
            "5,cor,1,0.42,0,0.03,0.4,0,0.03,,,\n");
}

TEST(TrajectoryOutputs, CsvColumnsAreTheTasks) {
  TempDir dir;
  TaskReport task = xyz_task();
  task.trajectory_columns = {"a", "b"};
  EXPECT_THROW(write_trajectory_csv({a_trial(0, true)}, task, dir.file("t.csv")),
               std::invalid_argument);
  task.trajectory_columns = {"a", "b", "c"};
  write_trajectory_csv({a_trial(0, true)}, task, dir.file("t.csv"));
  std::string header;
  std::getline(std::ifstream(dir.file("t.csv")) >> std::ws, header);
  EXPECT_EQ(header,
            "trial,segment,step,a,b,c,expert_a,expert_b,expert_c,executed_a,executed_b,executed_c");
  EvaluatedTrial narrow = a_trial(0, true);
  narrow.executed["cor"] = Eigen::MatrixXd::Zero(2, 2);
  EXPECT_THAT([&] { write_trajectory_csv({narrow}, task, dir.file("t.csv")); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("2 executed columns")));
}

// The pixel nearest `colour` in the column `x`, rows y-1 .. y+1 (lines are
// antialiased and may fall one row either side of the exact mapping).
cv::Vec3b nearest_of(const cv::Mat& image, int y, int x, const cv::Vec3b& colour) {
  cv::Vec3b best = image.at<cv::Vec3b>(y, x);
  for (int row = y - 1; row <= y + 1; ++row) {
    const cv::Vec3b candidate = image.at<cv::Vec3b>(row, x);
    if (cv::norm(candidate, colour) < cv::norm(best, colour)) best = candidate;
  }
  return best;
}

TEST(TrajectoryOutputs, FigureHasOnePanelPerTrialOnSharedAxes) {
  TempDir dir;
  std::vector<EvaluatedTrial> trials;
  for (int i = 0; i < 7; ++i) trials.push_back(a_trial(i, i != 6));
  write_trajectory_figure(trials, xyz_task(), {"pre", "cor", "post"}, dir.file("t.png"));
  const cv::Mat image = cv::imread(dir.file("t.png"), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, kTrajectoryColumns * kTrajectoryPanelWidth);
  EXPECT_EQ(image.rows, kTrajectoryHeader + 2 * kTrajectoryPanelHeight);
  // Panel 0's plot area: x from 0.39 to 0.43 (bottom to top), y from -0.21 to
  // 0.01 (left to right). The expert's line at x = 0.40 sits a quarter up, the
  // generated cor-MP (orange) at x = 0.42 three quarters up.
  const int left = 52, top = kTrajectoryHeader + 24;
  const int width = kTrajectoryPanelWidth - 52 - 12, height = kTrajectoryPanelHeight - 24 - 40;
  const int column = left + width / 2;
  const cv::Vec3b expert =
      nearest_of(image, top + height * 3 / 4, column, cv::Vec3b(190, 190, 190));
  const cv::Vec3b generated = nearest_of(image, top + height / 4, column, cv::Vec3b(20, 130, 240));
  EXPECT_NEAR(expert[0], 190, 30);
  EXPECT_NEAR(expert[1], 190, 30);
  EXPECT_NEAR(expert[2], 190, 30);
  EXPECT_GT(generated[2], 150);  // orange in BGR: much red, some green, little blue
  EXPECT_LT(generated[0], 120);
  // Trial 6 failed: its plot area is framed in red.
  const cv::Vec3b frame =
      nearest_of(image, kTrajectoryHeader + kTrajectoryPanelHeight + 24,
                 kTrajectoryPanelWidth + left + width / 2, cv::Vec3b(30, 30, 200));
  EXPECT_GT(frame[2], 150);
  EXPECT_LT(frame[1], 100);
}

TEST(TrajectoryOutputs, FigureDrawsTheExecutedPathDashedInADarkerShade) {
  TempDir dir;
  EvaluatedTrial trial = a_trial(0, true);
  Eigen::MatrixXd executed(2, 3);  // along y at x = 0.41, between the expert and the generated
  executed << 0.41, -0.20, 0.03, 0.41, 0.00, 0.03;
  trial.executed["cor"] = executed;
  write_trajectory_figure({trial}, xyz_task(), {"pre", "cor", "post"}, dir.file("t.png"));
  const cv::Mat image = cv::imread(dir.file("t.png"), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  // Halfway up the plot area (x from 0.39 to 0.43): dark orange dashes, white between them.
  const int left = 52, top = kTrajectoryHeader + 24;
  const int width = kTrajectoryPanelWidth - 52 - 12, height = kTrajectoryPanelHeight - 24 - 40;
  const cv::Vec3b dark(9, 58, 108);  // orange (20, 130, 240) at 0.45
  int dashes = 0, gaps = 0;
  for (int column = left + width / 4; column < left + 3 * width / 4; ++column) {
    const cv::Vec3b pixel = nearest_of(image, top + height / 2, column, dark);
    if (cv::norm(pixel, dark) < 60) {
      ++dashes;
    } else if (pixel[0] > 200 && pixel[1] > 200 && pixel[2] > 200) {
      ++gaps;
    }
  }
  EXPECT_GT(dashes, width / 8);
  EXPECT_GT(gaps, width / 16);
}

TEST(TrajectoryOutputs, FigureErrorsNameTheFunction) {
  TempDir dir;
  EXPECT_THROW(write_trajectory_figure({}, xyz_task(), {}, dir.file("t.png")),
               std::invalid_argument);
  TaskReport bad_axes = xyz_task();
  bad_axes.plot_vertical = 3;
  EXPECT_THROW(write_trajectory_figure({a_trial(0, true)}, bad_axes, {}, dir.file("t.png")),
               std::invalid_argument);
  EXPECT_THAT(
      [&] {
        write_trajectory_figure({a_trial(0, true)}, xyz_task(), {}, dir.file("missing/dir/t.png"));
      },
      ThrowsMessage<std::runtime_error>(HasSubstr("write_trajectory_figure: cannot write")));
}

}  // namespace
}  // namespace corrmp
