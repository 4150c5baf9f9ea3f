// Reconstruction grids and latent scatter plots drawn with OpenCV (autoencoder_figures.hpp).
#include "context/autoencoder/autoencoder_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "plot/plot_canvas.hpp"

namespace corrmp {
namespace {

const cv::Scalar kBlue(200, 80, 30);  // BGR

// An 8-bit image as BGR for drawing and writing.
cv::Mat to_bgr(const cv::Mat& image, const char* where) {
  if (image.empty() || image.depth() != CV_8U || (image.channels() != 3 && image.channels() != 1))
    throw std::invalid_argument(
        fmt::format("{}: images must be non-empty CV_8UC3 or CV_8UC1", where));
  cv::Mat bgr;
  cv::cvtColor(image, bgr, image.channels() == 3 ? cv::COLOR_RGB2BGR : cv::COLOR_GRAY2BGR);
  return bgr;
}

}  // namespace

void write_reconstruction_grid(const std::vector<cv::Mat>& images,
                               const std::vector<cv::Mat>& reconstructions,
                               const std::string& png_path) {
  constexpr const char* kWhere = "write_reconstruction_grid";
  if (images.empty() || images.size() != reconstructions.size())
    throw std::invalid_argument(fmt::format("{}: {} images but {} reconstructions", kWhere,
                                            images.size(), reconstructions.size()));
  const int count = static_cast<int>(images.size());
  const int columns = std::min(count, kGridColumns);
  const int blocks = (count + kGridColumns - 1) / kGridColumns;
  const int longest = std::max(images[0].rows, images[0].cols);
  const int scale = std::max(1, (kMinCellSide + longest - 1) / std::max(longest, 1));
  const cv::Size cell(images[0].cols * scale, images[0].rows * scale);
  cv::Mat canvas(2 * blocks * cell.height + (2 * blocks + 1) * kGridGap,
                 kGridLabelWidth + columns * cell.width + (columns + 1) * kGridGap, CV_8UC3,
                 kPlotGrey);
  for (int row = 0; row < 2 * blocks; ++row) {
    const int y = kGridGap + row * (cell.height + kGridGap) + cell.height / 2;
    put_text(canvas, row % 2 == 0 ? "image" : "decoded", cv::Point(6, y), 0.45, kPlotWhite);
  }
  for (int i = 0; i < count; ++i) {
    const int block = i / kGridColumns, column = i % kGridColumns;
    const int x = kGridLabelWidth + kGridGap + column * (cell.width + kGridGap);
    for (int which = 0; which < 2; ++which) {
      const cv::Mat& source = which == 0 ? images[i] : reconstructions[i];
      cv::Mat resized;
      cv::resize(to_bgr(source, kWhere), resized, cell, 0.0, 0.0, cv::INTER_NEAREST);
      const int y = kGridGap + (2 * block + which) * (cell.height + kGridGap);
      resized.copyTo(canvas(cv::Rect(x, y, cell.width, cell.height)));
    }
  }
  write_png(canvas, png_path, kWhere);
}

void write_latent_plot(const std::vector<double>& x_values, const Eigen::MatrixXd& latents,
                       const std::string& x_label, const std::string& png_path) {
  constexpr const char* kWhere = "write_latent_plot";
  if (x_values.empty() || latents.cols() == 0 ||
      latents.rows() != static_cast<Eigen::Index>(x_values.size()))
    throw std::invalid_argument(fmt::format("{}: {} x values for a {}x{} latent matrix", kWhere,
                                            x_values.size(), latents.rows(), latents.cols()));
  const int dims = static_cast<int>(latents.cols());
  const int columns = std::min(dims, kPlotColumns);
  const int rows = (dims + kPlotColumns - 1) / kPlotColumns;
  cv::Mat canvas(rows * kPanelHeight, columns * kPanelWidth, CV_8UC3, kPlotWhite);

  const auto [x_min, x_max] = padded_range(*std::min_element(x_values.begin(), x_values.end()),
                                           *std::max_element(x_values.begin(), x_values.end()));
  for (int k = 0; k < dims; ++k) {
    const cv::Point origin((k % kPlotColumns) * kPanelWidth, (k / kPlotColumns) * kPanelHeight);
    const auto [y_min, y_max] = padded_range(latents.col(k).minCoeff(), latents.col(k).maxCoeff());
    const PlotPanel panel{plot_area_in({origin.x, origin.y, kPanelWidth, kPanelHeight}), x_min,
                          x_max, y_min, y_max};
    panel.draw_frame(canvas, fmt::format("z{}", k), x_label);
    for (size_t i = 0; i < x_values.size(); ++i) {
      cv::circle(canvas, panel.to_pixel(x_values[i], latents(static_cast<Eigen::Index>(i), k)), 2,
                 kBlue, cv::FILLED, cv::LINE_AA);
    }
  }
  write_png(canvas, png_path, kWhere);
}

}  // namespace corrmp
