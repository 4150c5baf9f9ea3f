// Training of the context autoencoder (paper, Section III "Learning the Context": Adam with
// learning rate 3e-4 for 70 epochs on 360 of 400 images, the other 40 for testing), minimising
// the mean squared reconstruction error (conv_autoencoder.hpp).
//
// Each epoch visits the training images in a new random order (Fisher-Yates with rng) in
// minibatches of batch_size (the last one may be smaller) and takes one Adam step per minibatch.
//
// Steps run data-parallel over `threads` workers (data_parallel_trainer.hpp): deterministic for a
// seed and a thread count; other thread counts agree up to float summation order.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "context/autoencoder/autoencoder_params.hpp"
#include "context/autoencoder/conv_autoencoder.hpp"
#include "core/seeds.hpp"

namespace corrmp {

struct AutoencoderReport {
  std::vector<double> epoch_train_loss;  ///< per epoch: mean squared error over its minibatches
  double train_mse = 0.0;                ///< after training, over all training images
  double test_mse = 0.0;                 ///< after training, over the test images (0 if none)
  std::int64_t steps = 0;                ///< Adam steps taken
  int threads = 1;
  double seconds = 0.0;  ///< wall-clock time of the whole call
};

/// Trains `model` in place (params.learning_rate, epochs, batch_size, threads; the
/// architecture fields of params are not used: the model has its own). Images are converted
/// with images_to_batch (autoencoder_images.hpp). Throws std::invalid_argument for no training
/// images or a bad image, Interrupted (core/interrupt.hpp) when a signal arrives.
AutoencoderReport train_autoencoder(ConvAutoencoder<float>& model,
                                    const std::vector<cv::Mat>& train_images,
                                    const std::vector<cv::Mat>& test_images,
                                    const AutoencoderParams& params, Rng& rng,
                                    const std::string& label = "autoencoder");

/// The same on images already converted to batches (one image per row).
AutoencoderReport train_autoencoder(ConvAutoencoder<float>& model, nn::ConstMatRef<float> train,
                                    nn::ConstMatRef<float> test, const AutoencoderParams& params,
                                    Rng& rng, const std::string& label = "autoencoder");

/// A random split of `count` indices: round(count * test_fraction) test indices, the rest for
/// training, each list ascending (400 images, 0.1 -> 360 / 40 as in the paper).
struct TrainTestSplit {
  std::vector<int> train;
  std::vector<int> test;
};
TrainTestSplit split_train_test(int count, double test_fraction, Rng& rng);

}  // namespace corrmp
