// Tests of the autoencoder figures (paper, Section III "Learning the Context"): the
// reconstruction grid and the latent scatter plot are written as PNGs of the documented size.
#include "context/autoencoder/autoencoder_figures.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "synthetic_squares.hpp"

namespace corrmp {
namespace {

std::string temp_path(const std::string& name) { return ::testing::TempDir() + name; }

TEST(AutoencoderFigures, ReconstructionGridHasTheDocumentedLayout) {
  std::vector<cv::Mat> images, reconstructions;
  for (int i = 0; i < 5; ++i) {
    images.push_back(testing::square_image(2.0 * i, 16, 5));
    reconstructions.push_back(testing::square_image(2.0 * i + 0.5, 16, 5));
  }
  const std::string path = temp_path("ae_grid.png");
  write_reconstruction_grid(images, reconstructions, path);
  const cv::Mat png = cv::imread(path, cv::IMREAD_COLOR);
  ASSERT_FALSE(png.empty());
  // 16 px cells scaled by 8 to 128 px; 5 columns, 1 block of 2 rows; 4 px gaps, after the
  // 72 px margin of the row names.
  EXPECT_EQ(png.cols, 72 + 5 * 128 + 6 * 4);
  EXPECT_EQ(png.rows, 2 * 128 + 3 * 4);
  // The first original's top-left pixel is background grey; the file is BGR.
  EXPECT_EQ(png.at<cv::Vec3b>(4, 72 + 4), cv::Vec3b(128, 128, 128));
  // Centre of the first cell: inside the red square (RGB 230, 40, 40 -> BGR).
  EXPECT_EQ(png.at<cv::Vec3b>(4 + 64, 72 + 4 + 8 * 3), cv::Vec3b(40, 40, 230));
  // The margin names the rows in white (anti-aliased) text.
  const cv::Mat margin = png(cv::Rect(0, 0, 72, png.rows));
  cv::Mat white;
  cv::inRange(margin, cv::Scalar(200, 200, 200), cv::Scalar(255, 255, 255), white);
  EXPECT_GT(cv::countNonZero(white(cv::Rect(0, 0, 72, 132))), 20);
  EXPECT_GT(cv::countNonZero(white(cv::Rect(0, 136, 72, 132))), 20);
  std::remove(path.c_str());

  // Nine images need two blocks of eight columns.
  images.resize(9, images[0]);
  reconstructions.resize(9, reconstructions[0]);
  write_reconstruction_grid(images, reconstructions, path);
  const cv::Mat two_blocks = cv::imread(path, cv::IMREAD_COLOR);
  EXPECT_EQ(two_blocks.cols, 72 + 8 * 128 + 9 * 4);
  EXPECT_EQ(two_blocks.rows, 4 * 128 + 5 * 4);
  std::remove(path.c_str());
}

TEST(AutoencoderFigures, LatentPlotHasOnePanelPerDimension) {
  std::vector<double> x;
  Eigen::MatrixXd latents(20, 6);
  for (int i = 0; i < 20; ++i) {
    x.push_back(0.3 * i - 3.0);
    for (int k = 0; k < 6; ++k) latents(i, k) = std::sin(0.2 * i * (k + 1));
  }
  latents.col(5).setConstant(1.0);  // a constant dimension must not break the axis scaling
  const std::string path = temp_path("ae_latents.png");
  write_latent_plot(x, latents, "offset [cm]", path);
  const cv::Mat png = cv::imread(path, cv::IMREAD_COLOR);
  ASSERT_FALSE(png.empty());
  EXPECT_EQ(png.cols, kPlotColumns * kPanelWidth);  // 6 panels: 4 in the first row, 2 below
  EXPECT_EQ(png.rows, 2 * kPanelHeight);
  EXPECT_GT(cv::countNonZero(png.reshape(1) < 100), 500);  // axes, labels and points drawn
  std::remove(path.c_str());
}

TEST(AutoencoderFigures, RejectsMismatchedInputsAndUnwritablePaths) {
  const std::vector<cv::Mat> one{testing::square_image(1.0, 16, 5)};
  EXPECT_THROW(write_reconstruction_grid(one, {}, temp_path("x.png")), std::invalid_argument);
  EXPECT_THROW(write_latent_plot({1.0, 2.0}, Eigen::MatrixXd::Zero(3, 2), "x", temp_path("y.png")),
               std::invalid_argument);
  EXPECT_THROW(write_reconstruction_grid(one, one, "/nonexistent-dir/grid.png"),
               std::runtime_error);
}

}  // namespace
}  // namespace corrmp
