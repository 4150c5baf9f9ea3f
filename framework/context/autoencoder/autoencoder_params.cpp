// Validation and size arithmetic of the autoencoder architecture (autoencoder_params.hpp).
#include "context/autoencoder/autoencoder_params.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

namespace corrmp {

std::vector<int> AutoencoderArchitecture::encoder_sizes() const {
  std::vector<int> sizes;
  int size = image_size;
  for (int s : strides) {
    const int numerator = size + 2 * padding() - kernel_size;
    size = numerator < 0 || s < 1 ? 0 : numerator / s + 1;
    sizes.push_back(size);
  }
  return sizes;
}

void AutoencoderArchitecture::validate() const {
  auto fail = [this](const std::string& problem) {
    throw std::invalid_argument(
        fmt::format("autoencoder architecture ({}): {}", summary(), problem));
  };
  if (image_size < 1 || channels < 1 || kernel_size < 1 || latent_size < 1)
    fail("image_size, channels, kernel_size and latent_size must be >= 1");
  if (strides.empty()) fail("needs at least one convolution");
  if (strides.size() != filters.size())
    fail(fmt::format("{} strides but {} filters", strides.size(), filters.size()));
  for (size_t i = 0; i < strides.size(); ++i)
    if (strides[i] < 1 || filters[i] < 1) fail("strides and filters must be >= 1");
  int input = image_size;
  const std::vector<int> sizes = encoder_sizes();
  for (size_t i = 0; i < sizes.size(); ++i) {
    if (sizes[i] < 1)
      fail(fmt::format("a {}x{} image is too small for convolution {}", input, input, i));
    // The mirrored transposed convolution must restore `input` with output_padding < stride.
    const int restored = (sizes[i] - 1) * strides[i] - 2 * padding() + kernel_size;
    if (input - restored < 0 || input - restored >= strides[i])
      fail(fmt::format("convolution {} ({} -> {}) cannot be mirrored by a transposed convolution",
                       i, input, sizes[i]));
    input = sizes[i];
  }
}

std::string AutoencoderArchitecture::summary() const {
  return fmt::format("{}x{}x{}, kernel {}, strides [{}], filters [{}], latent {}", image_size,
                     image_size, channels, kernel_size, fmt::join(strides, ","),
                     fmt::join(filters, ","), latent_size);
}

double AutoencoderParams::training_bytes() const {
  const AutoencoderArchitecture a = architecture();
  const double k2 = static_cast<double>(kernel_size) * kernel_size;
  double activations = static_cast<double>(image_size) * image_size * channels;  // per image
  double weights = 0.0;
  int input_channels = channels;
  const std::vector<int> sizes = a.encoder_sizes();
  for (size_t i = 0; i < sizes.size(); ++i) {
    const double pixels = static_cast<double>(sizes[i]) * sizes[i];
    activations += pixels * (filters[i] + input_channels * k2);  // output and its im2col
    weights += static_cast<double>(filters[i]) * input_channels * k2;
    input_channels = filters[i];
  }
  const double flat = static_cast<double>(filters.back()) * sizes.back() * sizes.back();
  weights += flat * latent_size;
  // The decoder mirrors the encoder; values and gradients, all floats.
  const double per_image = 2.0 * 2.0 * activations * sizeof(float);
  return batch_size * per_image + 2.0 * 4.0 * weights * sizeof(float);
}

AutoencoderArchitecture AutoencoderParams::architecture() const {
  AutoencoderArchitecture a;
  a.image_size = image_size;
  a.channels = channels;
  a.strides = strides;
  a.filters = filters;
  a.kernel_size = kernel_size;
  a.latent_size = latent_size;
  a.validate();
  return a;
}

}  // namespace corrmp
