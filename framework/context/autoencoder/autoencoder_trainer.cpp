// Data-parallel minibatch training of the autoencoder (autoencoder_trainer.hpp).
#include "context/autoencoder/autoencoder_trainer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "context/autoencoder/autoencoder_images.hpp"
#include "context/autoencoder/data_parallel_trainer.hpp"
#include "core/interrupt.hpp"
#include "core/progress.hpp"
#include "core/thread_budget.hpp"
#include "nn/check.hpp"

namespace corrmp {
namespace {

void check_params(const AutoencoderParams& p) {
  if (p.epochs < 1 || p.batch_size < 1 || p.threads < 1 || !(p.learning_rate > 0.0))
    throw std::invalid_argument(fmt::format(
        "train_autoencoder: epochs ({}), batch_size ({}) and threads ({}) must be >= 1 and "
        "learning_rate ({}) > 0",
        p.epochs, p.batch_size, p.threads, p.learning_rate));
}

}  // namespace

AutoencoderReport train_autoencoder(ConvAutoencoder<float>& model, nn::ConstMatRef<float> train,
                                    nn::ConstMatRef<float> test, const AutoencoderParams& params,
                                    Rng& rng, const std::string& label) {
  const auto start = std::chrono::steady_clock::now();
  check_params(params);
  if (train.rows() == 0) throw std::invalid_argument("train_autoencoder: no training images");
  nn::check_shape("train_autoencoder", "training batch", train, train.rows(), model.image_values());
  nn::check_shape("train_autoencoder", "test batch", test, test.rows(), model.image_values());

  // params.threads shards (the results depend on it), on at most this run's
  // thread budget (they do not depend on that).
  DataParallelTrainer trainer(model, params.threads, params.learning_rate,
                              std::min(params.threads, thread_budget()));
  const nn::Index n = train.rows();
  const nn::Index batch_size = std::min<nn::Index>(params.batch_size, n);
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);

  AutoencoderReport report;
  report.threads = params.threads;
  Progress progress(label, params.epochs);
  for (int epoch = 0; epoch < params.epochs; ++epoch) {
    check_interrupt();
    for (nn::Index i = n - 1; i > 0; --i)
      std::swap(order[static_cast<size_t>(i)], order[static_cast<size_t>(rng.uniform_int(0, i))]);
    double squared_error = 0.0;  // summed over the epoch's images
    for (nn::Index begin = 0; begin < n; begin += batch_size) {
      const nn::Index batch = std::min(batch_size, n - begin);
      squared_error +=
          trainer.step(train, order.data() + begin, batch) * static_cast<double>(batch);
    }
    report.epoch_train_loss.push_back(squared_error / static_cast<double>(n));
    progress.advance(1, fmt::format("train MSE {:.5f}", report.epoch_train_loss.back()));
  }
  report.train_mse = trainer.evaluate(train);
  report.test_mse = test.rows() > 0 ? trainer.evaluate(test) : 0.0;
  report.steps = trainer.steps();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish(
      fmt::format("train MSE {:.5f}, test MSE {:.5f}", report.train_mse, report.test_mse));
  return report;
}

AutoencoderReport train_autoencoder(ConvAutoencoder<float>& model,
                                    const std::vector<cv::Mat>& train_images,
                                    const std::vector<cv::Mat>& test_images,
                                    const AutoencoderParams& params, Rng& rng,
                                    const std::string& label) {
  const nn::Mat<float> train = images_to_batch(train_images, model.image_shape());
  const nn::Mat<float> test = images_to_batch(test_images, model.image_shape());
  return train_autoencoder(model, train, test, params, rng, label);
}

TrainTestSplit split_train_test(int count, double test_fraction, Rng& rng) {
  if (count < 0 || !(test_fraction >= 0.0 && test_fraction <= 1.0))
    throw std::invalid_argument(
        fmt::format("split_train_test: count ({}) must be >= 0 and test_fraction ({}) in [0, 1]",
                    count, test_fraction));
  std::vector<int> order(static_cast<size_t>(count));
  std::iota(order.begin(), order.end(), 0);
  for (int i = count - 1; i > 0; --i)
    std::swap(order[static_cast<size_t>(i)], order[static_cast<size_t>(rng.uniform_int(0, i))]);
  const auto tests = static_cast<size_t>(std::llround(count * test_fraction));
  TrainTestSplit split;
  split.test.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(tests));
  split.train.assign(order.begin() + static_cast<std::ptrdiff_t>(tests), order.end());
  std::sort(split.test.begin(), split.test.end());
  std::sort(split.train.begin(), split.train.end());
  return split;
}

}  // namespace corrmp
