// Parameters of the convolutional autoencoder that learns the context of the correction
// primitive (paper, Section III "Learning the Context"): 2-D convolutions of kernel size 3,
// strides [2, 1, 2, 1, 2] and filters [32, 32, 64, 64, 64]; the encoder output is flattened and
// fed to a fully connected layer giving the latent (size 8); the decoder mirrors the encoder.
// Trained with Adam, learning rate 3e-4, for 70 epochs on 400 images (360 train, 40 test).
//
// AutoencoderArchitecture is what a model file records (conv_autoencoder.hpp);
// AutoencoderParams is the config section (architecture plus training), read through
// describe() by the config system (core/config/config_reader.hpp).
//
// Padding is (kernel_size - 1) / 2 ("same" for odd kernels), so with the paper's strides a
// 64 x 64 image shrinks 64 -> 32 -> 32 -> 16 -> 16 -> 8 and the flattened encoder output has
// filters.back() * 8 * 8 = 4096 entries.
#pragma once

#include <string>
#include <vector>

#include "core/config/field_rule.hpp"

namespace corrmp {

struct AutoencoderArchitecture {
  int image_size = 64;  ///< square input images, height = width
  int channels = 3;     ///< 3 for RGB, 1 for grey
  std::vector<int> strides{2, 1, 2, 1, 2};
  std::vector<int> filters{32, 32, 64, 64, 64};
  int kernel_size = 3;
  int latent_size = 8;

  /// (kernel_size - 1) / 2.
  int padding() const { return (kernel_size - 1) / 2; }
  /// Spatial size of the image after each encoder convolution (strides.size() entries).
  std::vector<int> encoder_sizes() const;
  /// Throws std::invalid_argument naming the problem (empty or unequal strides / filters,
  /// values < 1, an image too small for the strides).
  void validate() const;
  /// "64x64x3, kernel 3, strides [2,1,2,1,2], filters [32,32,64,64,64], latent 8".
  std::string summary() const;

  bool operator==(const AutoencoderArchitecture& o) const {
    return image_size == o.image_size && channels == o.channels && strides == o.strides &&
           filters == o.filters && kernel_size == o.kernel_size && latent_size == o.latent_size;
  }
  bool operator!=(const AutoencoderArchitecture& o) const { return !(*this == o); }
};

struct AutoencoderParams {
  int image_size = 64;
  int channels = 3;
  std::vector<int> strides{2, 1, 2, 1, 2};
  std::vector<int> filters{32, 32, 64, 64, 64};
  int kernel_size = 3;
  int latent_size = 8;
  double learning_rate = 3e-4;
  int epochs = 70;
  // Not stated in the paper. 16 gives 23 Adam steps per epoch of 360 images (about 1600 in 70
  // epochs) and shards of 8 images per thread with 2 threads.
  int batch_size = 16;
  int threads = 2;
  double test_fraction = 0.1;

  template <class Fields>
  void describe(Fields& f) {
    f("image_size", image_size, "images are resized to image_size x image_size", in_range(4, 1024));
    f("channels", channels, "image channels: 3 (RGB) or 1 (grey)", in_range(1, 3));
    f("strides", strides, "encoder convolution strides (the paper: [2, 1, 2, 1, 2])",
      in_range(1, 16));
    f("filters", filters, "encoder convolution filters (the paper: [32, 32, 64, 64, 64])",
      in_range(1, 4096));
    f("kernel_size", kernel_size, "convolution kernel size (the paper: 3)", in_range(1, 31));
    f("latent_size", latent_size, "latent (context) size (the paper: 8)", in_range(1, 65536));
    f("learning_rate", learning_rate, "Adam learning rate (the paper: 3e-4)", positive());
    f("epochs", epochs, "training epochs (the paper: 70)", in_range(1, 1000000));
    f("batch_size", batch_size, "images per Adam step (not given in the paper)",
      in_range(1, 65536));
    f("threads", threads,
      "data-parallel shards of each minibatch, run on as many threads as the run's --threads "
      "allow (the results depend on this value, not on the cores)",
      in_range(1, 64));
    f("test_fraction", test_fraction, "share of the images held out (the paper: 40 of 400)",
      in_range(0.0, 0.9));
  }

  /// The architecture part, validated (throws std::invalid_argument).
  AutoencoderArchitecture architecture() const;
  /// Peak memory of training, in bytes (a load-time estimate: one batch's activations, their
  /// gradients and im2col buffers; weights with Adam's moments).
  double training_bytes() const;
};

}  // namespace corrmp
