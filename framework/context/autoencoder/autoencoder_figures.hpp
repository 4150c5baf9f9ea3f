// Figures of the context autoencoder (paper, Section III "Learning the Context"): how well it
// reconstructs the scene images and how its latent dimensions (the context of the correction
// primitive) vary with a known scene quantity such as the corridor offset.
//
// write_reconstruction_grid: up to kGridColumns images per block; each block is a row of
// originals with the row of their reconstructions below. Every cell is the size of the first
// original scaled by an integer factor so that its longer side is at least kMinCellSide pixels
// (nearest-neighbour, so pixels stay visible); reconstructions are resized to the cell. Cells are
// separated and framed by kGridGap grey pixels, after a kGridLabelWidth margin on the left that
// names each row ("image", "decoded"):
//   width  = label + columns cell_width + (columns + 1) gap,  columns = min(count, kGridColumns)
//   height = 2 blocks cell_height + (2 blocks + 1) gap, blocks = ceil(count / kGridColumns)
// write_latent_plot: one kPanelWidth x kPanelHeight scatter panel per latent dimension (title
// "z<k>", min / max tick labels on both axes, x_label under the x axis), kPlotColumns panels per
// row: width = min(latent, kPlotColumns) kPanelWidth, height = ceil(latent / kPlotColumns)
// kPanelHeight.
// Images are RGB (CV_8UC3) or grey (CV_8UC1); files are written with cv::imwrite (PNG), and a
// failed write throws std::runtime_error naming the path.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace corrmp {

constexpr int kGridColumns = 8;
constexpr int kMinCellSide = 128;
constexpr int kGridGap = 4;
constexpr int kGridLabelWidth = 72;
constexpr int kPanelWidth = 280;
constexpr int kPanelHeight = 210;
constexpr int kPlotColumns = 4;

/// Originals above their reconstructions (equal, non-zero counts; std::invalid_argument
/// otherwise).
void write_reconstruction_grid(const std::vector<cv::Mat>& images,
                               const std::vector<cv::Mat>& reconstructions,
                               const std::string& png_path);

/// One scatter panel per latent column against x_values (latents.rows() == x_values.size()).
void write_latent_plot(const std::vector<double>& x_values, const Eigen::MatrixXd& latents,
                       const std::string& x_label, const std::string& png_path);

}  // namespace corrmp
