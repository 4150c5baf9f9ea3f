// Conversions between cv::Mat images and autoencoder batches (autoencoder_images.hpp).
#include "context/autoencoder/autoencoder_images.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "nn/check.hpp"

namespace corrmp {

void image_to_row(const cv::Mat& image, const nn::ImageShape& shape, float* row) {
  if (shape.height != shape.width || shape.height < 1)
    throw std::invalid_argument(
        fmt::format("autoencoder images must be square, got {}x{}", shape.height, shape.width));
  if (image.empty()) throw std::invalid_argument("autoencoder image: empty image");
  if (image.depth() != CV_8U || image.channels() != shape.channels)
    throw std::invalid_argument(fmt::format(
        "autoencoder image: expected 8-bit unsigned with {} channel(s), got depth {} with {}",
        shape.channels, image.depth(), image.channels()));
  const int side = static_cast<int>(shape.height);
  cv::Mat sized = image;
  if (image.rows != side || image.cols != side)
    cv::resize(image, sized, cv::Size(side, side), 0.0, 0.0, cv::INTER_AREA);
  const int channels = static_cast<int>(shape.channels);
  const nn::Index plane = static_cast<nn::Index>(side) * side;
  constexpr float kScale = 1.0f / 255.0f;
  for (int h = 0; h < side; ++h) {
    const unsigned char* pixel = sized.ptr<unsigned char>(h);
    for (int w = 0; w < side; ++w, pixel += channels)
      for (int c = 0; c < channels; ++c)
        row[c * plane + static_cast<nn::Index>(h) * side + w] = pixel[c] * kScale;
  }
}

nn::Mat<float> images_to_batch(const std::vector<cv::Mat>& images, const nn::ImageShape& shape) {
  nn::Mat<float> batch(static_cast<nn::Index>(images.size()), shape.size());
  for (size_t i = 0; i < images.size(); ++i) {
    try {
      image_to_row(images[i], shape, batch.row(static_cast<nn::Index>(i)).data());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("image {}: {}", i, e.what()));
    }
  }
  return batch;
}

cv::Mat row_to_image(const float* row, const nn::ImageShape& shape) {
  const int channels = static_cast<int>(shape.channels);
  const int height = static_cast<int>(shape.height), width = static_cast<int>(shape.width);
  if (channels != 1 && channels != 3)
    throw std::invalid_argument(
        fmt::format("row_to_image: {} channels (1 or 3 expected)", channels));
  cv::Mat image(height, width, CV_8UC(channels));
  const nn::Index plane = static_cast<nn::Index>(height) * width;
  for (int h = 0; h < height; ++h) {
    unsigned char* pixel = image.ptr<unsigned char>(h);
    for (int w = 0; w < width; ++w, pixel += channels) {
      for (int c = 0; c < channels; ++c) {
        const float v =
            std::clamp(row[c * plane + static_cast<nn::Index>(h) * width + w], 0.0f, 1.0f);
        pixel[c] = static_cast<unsigned char>(std::lround(v * 255.0f));
      }
    }
  }
  return image;
}

std::vector<cv::Mat> batch_to_images(nn::ConstMatRef<float> batch, const nn::ImageShape& shape) {
  nn::check_shape("batch_to_images", "batch", batch, batch.rows(), shape.size());
  std::vector<cv::Mat> images;
  images.reserve(static_cast<size_t>(batch.rows()));
  for (nn::Index i = 0; i < batch.rows(); ++i)
    images.push_back(row_to_image(batch.row(i).data(), shape));
  return images;
}

Eigen::MatrixXd encode_images(ConvAutoencoder<float>& model, const std::vector<cv::Mat>& images) {
  const nn::Mat<float> batch = images_to_batch(images, model.image_shape());
  return model.encode(batch).cast<double>();
}

std::vector<cv::Mat> reconstruct_images(ConvAutoencoder<float>& model,
                                        const std::vector<cv::Mat>& images) {
  const nn::Mat<float> batch = images_to_batch(images, model.image_shape());
  return batch_to_images(model.reconstruct(batch), model.image_shape());
}

}  // namespace corrmp
