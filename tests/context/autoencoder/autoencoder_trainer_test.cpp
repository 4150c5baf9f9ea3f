// Tests of the autoencoder training (paper, Section III "Learning the Context"): it learns a
// synthetic scene set whose only content is a position, its latent encodes that position, and
// the data-parallel steps are deterministic and agree across thread counts.
#include "context/autoencoder/autoencoder_trainer.hpp"

#include <gtest/gtest.h>

#include <thread>

#include "core/thread_budget.hpp"

#include <Eigen/Dense>
#include <set>
#include <stdexcept>

#include "context/autoencoder/autoencoder_images.hpp"
#include "context/autoencoder/data_parallel_trainer.hpp"
#include "synthetic_squares.hpp"

namespace corrmp {
namespace {

constexpr int kSize = 16;  // image side
constexpr int kSide = 5;   // square side

AutoencoderParams small_params() {
  AutoencoderParams p;
  p.image_size = kSize;
  p.strides = {2, 2};
  p.filters = {8, 16};
  p.latent_size = 4;
  p.learning_rate = 3e-3;
  p.batch_size = 16;
  p.threads = 2;
  return p;
}

// Least-squares fit of y ~ [z 1] on the training rows; R^2 of its predictions on the test rows.
double heldout_r2(const Eigen::MatrixXd& z_train, const std::vector<double>& y_train,
                  const Eigen::MatrixXd& z_test, const std::vector<double>& y_test) {
  auto with_bias = [](const Eigen::MatrixXd& z) {
    Eigen::MatrixXd a(z.rows(), z.cols() + 1);
    a << z, Eigen::VectorXd::Ones(z.rows());
    return a;
  };
  const Eigen::VectorXd fit = with_bias(z_train).colPivHouseholderQr().solve(
      Eigen::Map<const Eigen::VectorXd>(y_train.data(), static_cast<Eigen::Index>(y_train.size())));
  const Eigen::Map<const Eigen::VectorXd> truth(y_test.data(),
                                                static_cast<Eigen::Index>(y_test.size()));
  const Eigen::VectorXd predicted = with_bias(z_test) * fit;
  return 1.0 - (predicted - truth).squaredNorm() / (truth.array() - truth.mean()).square().sum();
}

std::vector<Eigen::VectorXf> weights_of(ConvAutoencoder<float>& model) {
  std::vector<Eigen::VectorXf> weights;
  for (const auto& p : model.parameters()) weights.push_back(p.values());
  return weights;
}

AutoencoderReport train_squares(ConvAutoencoder<float>& model, const AutoencoderParams& p,
                                int count, std::uint64_t seed) {
  Rng data_rng(seed);
  const testing::SquareSet train = testing::square_set(count, kSize, kSide, data_rng);
  Rng rng(seed + 1);
  return train_autoencoder(model, train.images, {}, p, rng, "test");
}

TEST(AutoencoderTrainer, LearnsTheSquaresAndItsLatentEncodesThePosition) {
  Rng data_rng(3);
  const testing::SquareSet train = testing::square_set(100, kSize, kSide, data_rng);
  const testing::SquareSet test = testing::square_set(30, kSize, kSide, data_rng);
  AutoencoderParams p = small_params();
  p.epochs = 60;
  nn::Rng init(1);
  ConvAutoencoder<float> model(p.architecture(), init);
  Rng rng(5);
  const AutoencoderReport report = train_autoencoder(model, train.images, test.images, p, rng);

  ASSERT_EQ(report.epoch_train_loss.size(), 60u);
  EXPECT_EQ(report.steps, 60 * 7);  // ceil(100 / 16) steps per epoch
  EXPECT_EQ(report.threads, 2);
  // Baseline: predicting the mean training image for every test image.
  const nn::Mat<float> train_batch = images_to_batch(train.images, model.image_shape());
  const nn::Mat<float> test_batch = images_to_batch(test.images, model.image_shape());
  const Eigen::RowVectorXd mean = train_batch.cast<double>().colwise().mean();
  const double mean_image_mse =
      (test_batch.cast<double>().rowwise() - mean).squaredNorm() / test_batch.size();
  EXPECT_GT(mean_image_mse, 0.007);
  // Over init seeds 1..8 the test MSE was 2.1e-4 .. 3.4e-4 and R^2 0.979 .. 0.997.
  EXPECT_LT(report.test_mse, 0.001);
  EXPECT_LT(report.test_mse, 0.15 * mean_image_mse);
  EXPECT_LT(report.train_mse, 0.001);
  EXPECT_LT(report.epoch_train_loss.back(), 0.2 * report.epoch_train_loss.front());
  EXPECT_NEAR(report.test_mse, model.reconstruction_mse(test_batch), 1e-6);

  const double r2 = heldout_r2(encode_images(model, train.images), train.positions,
                               encode_images(model, test.images), test.positions);
  EXPECT_GT(r2, 0.9);
}

TEST(AutoencoderTrainer, PaperArchitectureLossDecreasesOn64x64Images) {
  AutoencoderParams p;  // the paper's architecture
  p.learning_rate = 1e-3;
  p.batch_size = 4;
  p.epochs = 8;
  Rng data_rng(8);
  const testing::SquareSet train = testing::square_set(32, 64, 16, data_rng);
  nn::Rng init(1);
  ConvAutoencoder<float> model(p.architecture(), init);
  Rng rng(2);
  const AutoencoderReport report = train_autoencoder(model, train.images, {}, p, rng);
  ASSERT_EQ(report.epoch_train_loss.size(), 8u);
  EXPECT_LT(report.epoch_train_loss.back(), 0.8 * report.epoch_train_loss.front());
  EXPECT_LT(report.train_mse, report.epoch_train_loss.front());
}

TEST(AutoencoderTrainer, SameSeedAndThreadsGiveIdenticalWeights) {
  AutoencoderParams p = small_params();
  p.epochs = 4;
  p.batch_size = 7;
  nn::Rng init_a(2), init_b(2);
  ConvAutoencoder<float> a(p.architecture(), init_a), b(p.architecture(), init_b);
  const AutoencoderReport ra = train_squares(a, p, 40, 11);
  const AutoencoderReport rb = train_squares(b, p, 40, 11);
  EXPECT_EQ(ra.epoch_train_loss, rb.epoch_train_loss);
  EXPECT_EQ(weights_of(a), weights_of(b));
}

// A run given fewer cores (a sweep's job, --threads 1) runs its shards on
// fewer workers and gets exactly the same model.
TEST(AutoencoderTrainer, TheThreadBudgetDoesNotChangeTheResult) {
  AutoencoderParams p = small_params();
  p.epochs = 3;
  p.batch_size = 8;
  p.threads = 3;
  std::vector<std::vector<Eigen::VectorXf>> weights;
  for (int budget : {1, 2, 3}) {
    set_thread_budget(budget);
    nn::Rng init(7);
    ConvAutoencoder<float> model(p.architecture(), init);
    train_squares(model, p, 37, 21);
    weights.push_back(weights_of(model));
  }
  set_thread_budget(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  EXPECT_EQ(weights[0], weights[1]);
  EXPECT_EQ(weights[0], weights[2]);
}

// The same with stride-1 layers (Winograd convolutions, nn/winograd_conv3x3.hpp) and more
// parameter entries than one block of the trainer's parallel gradient sum and Adam update.
TEST(AutoencoderTrainer, TheThreadBudgetDoesNotChangeTheResultWithWinogradLayers) {
  AutoencoderParams p = small_params();
  p.strides = {2, 1};
  p.filters = {8, 12};
  p.epochs = 2;
  p.batch_size = 8;
  p.threads = 3;
  std::vector<std::vector<Eigen::VectorXf>> weights;
  for (int budget : {1, 2, 3}) {
    set_thread_budget(budget);
    nn::Rng init(5);
    ConvAutoencoder<float> model(p.architecture(), init);
    train_squares(model, p, 29, 13);
    weights.push_back(weights_of(model));
  }
  set_thread_budget(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  EXPECT_EQ(weights[0], weights[1]);
  EXPECT_EQ(weights[0], weights[2]);
}

TEST(AutoencoderTrainer, ThreadCountsGiveTheSameLossCurve) {
  AutoencoderParams p = small_params();
  p.epochs = 5;
  p.batch_size = 8;  // 37 images: the last minibatch has 5, and 3 threads split unevenly
  std::vector<std::vector<double>> curves;
  for (int threads : {1, 2, 3}) {
    p.threads = threads;
    nn::Rng init(7);
    ConvAutoencoder<float> model(p.architecture(), init);
    curves.push_back(train_squares(model, p, 37, 21).epoch_train_loss);
  }
  // Observed: relative differences of about 2e-8 after 5 epochs.
  for (size_t t = 1; t < curves.size(); ++t)
    for (size_t e = 0; e < curves[0].size(); ++e)
      EXPECT_NEAR(curves[t][e], curves[0][e], 1e-5 * curves[0][e]) << "threads " << t + 1;
}

// With both kinds of Winograd layers (16 channels: nn/winograd_stride2_conv3x3.hpp too), whose
// transformed weights the replicas read from the model (data_parallel_trainer.hpp): one thread
// without replicas and two with one agree up to float rounding.
TEST(AutoencoderTrainer, ThreadCountsGiveTheSameLossCurveWithWinogradLayers) {
  AutoencoderParams p = small_params();
  p.strides = {2, 1, 2};
  p.filters = {16, 16, 16};
  p.epochs = 3;
  p.batch_size = 8;
  std::vector<std::vector<double>> curves;
  for (int threads : {1, 2}) {
    p.threads = threads;
    nn::Rng init(9);
    ConvAutoencoder<float> model(p.architecture(), init);
    curves.push_back(train_squares(model, p, 37, 23).epoch_train_loss);
  }
  for (size_t e = 0; e < curves[0].size(); ++e)
    EXPECT_NEAR(curves[1][e], curves[0][e], 1e-5 * curves[0][e]) << "epoch " << e;
}

TEST(AutoencoderTrainer, EmptyShardsAreSkippedExactly) {
  // With minibatches of one image the second worker's shard is empty, so 2 threads compute
  // exactly what 1 thread does.
  AutoencoderParams p = small_params();
  p.epochs = 2;
  p.batch_size = 1;
  std::vector<std::vector<Eigen::VectorXf>> weights;
  for (int threads : {1, 2}) {
    p.threads = threads;
    nn::Rng init(7);
    ConvAutoencoder<float> model(p.architecture(), init);
    train_squares(model, p, 10, 31);
    weights.push_back(weights_of(model));
  }
  EXPECT_EQ(weights[0], weights[1]);
}

TEST(AutoencoderTrainer, RejectsMissingOrMisshapenData) {
  AutoencoderParams p = small_params();
  nn::Rng init(1);
  ConvAutoencoder<float> model(p.architecture(), init);
  Rng rng(1);
  EXPECT_THROW(train_autoencoder(model, std::vector<cv::Mat>{}, {}, p, rng), std::invalid_argument);
  const nn::Mat<float> wrong(3, 10);
  EXPECT_THROW(train_autoencoder(model, wrong, wrong, p, rng), std::invalid_argument);
  p.batch_size = 0;
  const std::vector<cv::Mat> one{testing::square_image(1.0, kSize, kSide)};
  EXPECT_THROW(train_autoencoder(model, one, {}, p, rng), std::invalid_argument);
}

TEST(AutoencoderTrainer, SplitIsThePapers360And40) {
  Rng rng(9);
  const TrainTestSplit split = split_train_test(400, 0.1, rng);
  EXPECT_EQ(split.train.size(), 360u);
  EXPECT_EQ(split.test.size(), 40u);
  std::set<int> all(split.train.begin(), split.train.end());
  all.insert(split.test.begin(), split.test.end());
  EXPECT_EQ(all.size(), 400u);
  EXPECT_TRUE(std::is_sorted(split.test.begin(), split.test.end()));
  Rng again(9);
  EXPECT_EQ(split_train_test(400, 0.1, again).test, split.test);
  EXPECT_THROW(split_train_test(10, 1.5, rng), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
