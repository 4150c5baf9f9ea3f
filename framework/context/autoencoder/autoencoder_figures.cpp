// Reconstruction grids and latent scatter plots drawn with OpenCV (autoencoder_figures.hpp).
#include "context/autoencoder/autoencoder_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace corrmp {
namespace {

const cv::Scalar kWhite(255, 255, 255);
const cv::Scalar kGrey(128, 128, 128);
const cv::Scalar kBlack(0, 0, 0);
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

void write_png(const cv::Mat& canvas, const std::string& path, const char* where) {
  bool ok = false;
  try {
    ok = cv::imwrite(path, canvas);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(fmt::format("{}: cannot write '{}': {}", where, path, e.what()));
  }
  if (!ok) throw std::runtime_error(fmt::format("{}: cannot write '{}'", where, path));
}

// Short tick label: 3 significant digits.
std::string tick(double value) { return fmt::format("{:.3g}", value); }

void put_text(cv::Mat& canvas, const std::string& text, cv::Point origin, double scale = 0.4) {
  cv::putText(canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, scale, kBlack, 1, cv::LINE_AA);
}

// [lo, hi] widened to a non-empty range.
std::pair<double, double> range_of(double lo, double hi) {
  if (hi > lo) return {lo, hi};
  const double pad = std::max(1e-9, std::abs(lo) * 0.05 + 0.5);
  return {lo - pad, hi + pad};
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
                 columns * cell.width + (columns + 1) * kGridGap, CV_8UC3, kGrey);
  for (int i = 0; i < count; ++i) {
    const int block = i / kGridColumns, column = i % kGridColumns;
    const int x = kGridGap + column * (cell.width + kGridGap);
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
  cv::Mat canvas(rows * kPanelHeight, columns * kPanelWidth, CV_8UC3, kWhite);

  const auto [x_min, x_max] = range_of(*std::min_element(x_values.begin(), x_values.end()),
                                       *std::max_element(x_values.begin(), x_values.end()));
  // Plot area inside each panel: margins for the title, tick labels and x label.
  constexpr int kLeft = 52, kRight = 12, kTop = 24, kBottom = 40;
  const int plot_w = kPanelWidth - kLeft - kRight, plot_h = kPanelHeight - kTop - kBottom;
  for (int k = 0; k < dims; ++k) {
    const cv::Point origin((k % kPlotColumns) * kPanelWidth, (k / kPlotColumns) * kPanelHeight);
    const auto [y_min, y_max] = range_of(latents.col(k).minCoeff(), latents.col(k).maxCoeff());
    const cv::Point top_left = origin + cv::Point(kLeft, kTop);
    const cv::Point bottom_right = top_left + cv::Point(plot_w, plot_h);
    cv::rectangle(canvas, top_left, bottom_right, kBlack, 1);
    put_text(canvas, fmt::format("z{}", k), origin + cv::Point(kLeft + plot_w / 2 - 8, 16), 0.5);
    // Ticks and labels at the ends of both axes.
    cv::line(canvas, {top_left.x - 4, top_left.y}, top_left, kBlack);
    cv::line(canvas, {top_left.x - 4, bottom_right.y}, {top_left.x, bottom_right.y}, kBlack);
    cv::line(canvas, {top_left.x, bottom_right.y}, {top_left.x, bottom_right.y + 4}, kBlack);
    cv::line(canvas, bottom_right, {bottom_right.x, bottom_right.y + 4}, kBlack);
    put_text(canvas, tick(y_max), origin + cv::Point(2, kTop + 4));
    put_text(canvas, tick(y_min), origin + cv::Point(2, kTop + plot_h + 4));
    put_text(canvas, tick(x_min), {top_left.x - 8, bottom_right.y + 16});
    put_text(canvas, tick(x_max), {bottom_right.x - 24, bottom_right.y + 16});
    put_text(canvas, x_label,
             {top_left.x + plot_w / 2 - 3 * static_cast<int>(x_label.size()), bottom_right.y + 32});
    for (size_t i = 0; i < x_values.size(); ++i) {
      const double u = (x_values[i] - x_min) / (x_max - x_min);
      const double v = (latents(static_cast<Eigen::Index>(i), k) - y_min) / (y_max - y_min);
      const cv::Point p(top_left.x + static_cast<int>(std::lround(u * plot_w)),
                        bottom_right.y - static_cast<int>(std::lround(v * plot_h)));
      cv::circle(canvas, p, 2, kBlue, cv::FILLED, cv::LINE_AA);
    }
  }
  write_png(canvas, png_path, kWhere);
}

}  // namespace corrmp
