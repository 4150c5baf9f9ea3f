// The knotting figure colours each failed test trial by its failure category, one colour per
// declared category, and its legend lists the categories that occur.
#include "envs/rope_knot/rope_knot_figure.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

namespace corrmp {
namespace {

const std::vector<std::string> kCategories{
    "missed enclose", "near miss",          "knot lost while tightening",
    "physics fault",  "invalid trajectory", "out of reach",
    "joint limit",    "self collision",     "tracking error"};

EvaluatedTrial trial(bool success, const std::string& failure, double dx = 0.01) {
  EvaluatedTrial t;
  t.success = success;
  t.failure = failure;
  Eigen::VectorXd context(3);
  context << dx, 0.02, 0.0;
  t.contexts["cor"] = context;
  return t;
}

bool same(const cv::Scalar& a, const cv::Scalar& b) { return a == b; }

TEST(KnottingFigure, EachCategoryHasItsOwnColour) {
  std::vector<cv::Scalar> colours;
  for (const auto& category : kCategories) {
    const cv::Scalar colour =
        knotting_trial_colour(trial(false, category + ": detail"), kCategories);
    for (const auto& other : colours) EXPECT_FALSE(same(colour, other)) << category;
    colours.push_back(colour);
  }
  const cv::Scalar tied = knotting_trial_colour(trial(true, ""), kCategories);
  const cv::Scalar other = knotting_trial_colour(trial(false, "something else"), kCategories);
  for (const auto& colour : colours) {
    EXPECT_FALSE(same(colour, tied));
    EXPECT_FALSE(same(colour, other));
  }
  // A category keeps its colour when a task declares more categories after it.
  const std::vector<std::string> first_two(kCategories.begin(), kCategories.begin() + 2);
  EXPECT_TRUE(same(knotting_trial_colour(trial(false, "near miss"), first_two), colours[1]));
}

TEST(KnottingFigure, TheLegendListsTheCategoriesThatOccurInDeclaredOrder) {
  const std::vector<EvaluatedTrial> trials{
      trial(true, ""),           trial(false, "tracking error: joint 3"),
      trial(false, "near miss"), trial(false, "out of reach: left arm"),
      trial(false, "near miss"), trial(false, "???")};
  const std::vector<KnottingLegendEntry> legend = knotting_failure_legend(trials, kCategories);
  ASSERT_EQ(legend.size(), 4u);
  EXPECT_EQ(legend[0].text, "near miss");
  EXPECT_EQ(legend[1].text, "out of reach");
  EXPECT_EQ(legend[2].text, "tracking error");
  EXPECT_EQ(legend[3].text, "other failure");
  EXPECT_TRUE(same(legend[1].colour, knotting_trial_colour(trials[3], kCategories)));
  EXPECT_TRUE(knotting_failure_legend({trial(true, "")}, kCategories).empty());
}

// The number of pixels of exactly `colour` (BGR) in the image.
int pixels_of(const cv::Mat& image, const cv::Scalar& colour) {
  const cv::Vec3b bgr(static_cast<uchar>(colour[0]), static_cast<uchar>(colour[1]),
                      static_cast<uchar>(colour[2]));
  int n = 0;
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) n += image.at<cv::Vec3b>(r, c) == bgr;
  }
  return n;
}

TEST(KnottingFigure, AFailedTrialIsDrawnInItsCategorysColour) {
  const auto png = std::filesystem::temp_directory_path() /
                   ("corrmp-knotting-" + std::to_string(::getpid()) + ".png");
  const std::vector<EvaluatedTrial> trials{trial(true, "", 0.0),
                                           trial(false, "out of reach: right arm", 0.02)};
  write_knotting_figure(trials, {}, kCategories, png.string());
  const cv::Mat image = cv::imread(png.string(), cv::IMREAD_COLOR);
  std::filesystem::remove(png);
  ASSERT_FALSE(image.empty());
  const cv::Scalar reach = knotting_trial_colour(trials[1], kCategories);
  EXPECT_GT(pixels_of(image, reach), 20);  // the trial's dot and its legend entry
  const cv::Scalar missed = knotting_trial_colour(trial(false, "missed enclose"), kCategories);
  EXPECT_EQ(pixels_of(image, missed), 0);  // no such failure: neither drawn nor in the legend
}

}  // namespace
}  // namespace corrmp
