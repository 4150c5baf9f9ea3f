// Camera images <-> autoencoder batches (paper, Section III "Learning the Context": the encoder
// receives an image of the scene and its latent vector is the context).
//
// An image is a cv::Mat of 8-bit unsigned values, CV_8UC3 in RGB order for 3 channels (CV_8UC1
// for 1), of any size. It becomes one batch row (nn/tensor.hpp) of C x S x S floats in C, H, W
// order, S = image_size, value = pixel / 255 in [0, 1]:
//   row[(c S + h) S + w] = image(h, w)[c] / 255
// Images of another size are first resized to S x S with cv::INTER_AREA (the aspect ratio is not
// kept). The way back rounds clamp(value, 0, 1) * 255 to the nearest integer.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "context/autoencoder/conv_autoencoder.hpp"
#include "nn/conv_geometry.hpp"
#include "nn/tensor.hpp"

namespace corrmp {

/// Writes one image into `row` (shape.size() floats); throws std::invalid_argument for an empty
/// image, a depth other than 8-bit unsigned or a channel count other than shape.channels.
void image_to_row(const cv::Mat& image, const nn::ImageShape& shape, float* row);

/// The batch (N x shape.size()) of N images; shape.height must equal shape.width.
nn::Mat<float> images_to_batch(const std::vector<cv::Mat>& images, const nn::ImageShape& shape);

/// One batch row as an 8-bit image (CV_8UC3 RGB or CV_8UC1), shape.height x shape.width.
cv::Mat row_to_image(const float* row, const nn::ImageShape& shape);

/// Every row of `batch` as an image.
std::vector<cv::Mat> batch_to_images(nn::ConstMatRef<float> batch, const nn::ImageShape& shape);

/// The latents (N x latent_size) of N images.
Eigen::MatrixXd encode_images(ConvAutoencoder<float>& model, const std::vector<cv::Mat>& images);

/// The reconstructions of N images, each image_size x image_size.
std::vector<cv::Mat> reconstruct_images(ConvAutoencoder<float>& model,
                                        const std::vector<cv::Mat>& images);

}  // namespace corrmp
