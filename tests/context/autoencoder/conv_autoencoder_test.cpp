// Tests of the context autoencoder model (paper, Section III "Learning the Context"): gradients
// of the whole network against finite differences, the paper's shapes, parameters from config,
// model files, and image conversions.
#include "context/autoencoder/conv_autoencoder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

#include "context/autoencoder/autoencoder_images.hpp"
#include "core/config/config_error.hpp"
#include "core/config/config_reader.hpp"
#include "synthetic_squares.hpp"

namespace corrmp {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using MatD = nn::Mat<double>;

AutoencoderArchitecture tiny_architecture(int image_size) {
  AutoencoderArchitecture a;
  a.image_size = image_size;
  a.channels = 2;
  a.strides = {2, 1};
  a.filters = {3, 4};
  a.kernel_size = 3;
  a.latent_size = 2;
  return a;
}

MatD random_images(nn::Index count, nn::Index values, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  MatD m(count, values);
  for (nn::Index i = 0; i < m.size(); ++i) m.data()[i] = u(rng);
  return m;
}

// Every parameter gradient of train_step against central differences of reconstruction_mse.
void check_gradients(const AutoencoderArchitecture& a, double gradient_scale) {
  nn::Rng init(3);
  ConvAutoencoder<double> model(a, init);
  std::mt19937_64 rng(17);
  const MatD images = random_images(3, model.image_values(), rng);
  auto params = model.parameters();
  // PyTorch's initialisation shrinks activations layer by layer, which leaves the first layers'
  // gradients near the round-off of the loss; doubling every weight keeps them measurable.
  for (const auto& p : params) p.values() *= 2.0;
  nn::zero_grad(params);
  const double loss = model.train_step(images, gradient_scale);
  EXPECT_NEAR(loss, model.reconstruction_mse(images), 1e-14);

  const double h = 1e-6;
  for (const auto& p : params) {
    Eigen::VectorXd numeric(p.size());
    for (nn::Index i = 0; i < p.size(); ++i) {
      const double saved = p.value[i];
      p.value[i] = saved + h;
      const double up = model.reconstruction_mse(images);
      p.value[i] = saved - h;
      const double down = model.reconstruction_mse(images);
      p.value[i] = saved;
      numeric[i] = gradient_scale * (up - down) / (2 * h);
    }
    const Eigen::VectorXd analytic = p.grads();
    ASSERT_GT(analytic.norm(), 1e-10) << p.name << ": zero gradient";
    const double error = (analytic - numeric).norm() / std::max(analytic.norm(), numeric.norm());
    EXPECT_LE(error, 1e-6) << p.name << "\nanalytic " << analytic.transpose() << "\nnumeric  "
                           << numeric.transpose();
  }
}

TEST(AutoencoderGrad, WholeModelMatchesFiniteDifferences) {
  check_gradients(tiny_architecture(8), 1.0);  // 8 -> 4 -> 4: output_padding 1 on the way back
}

TEST(AutoencoderGrad, OddImageSizeAndGradientScale) {
  check_gradients(tiny_architecture(7), 0.25);  // 7 -> 4 -> 4: output_padding 0
}

TEST(ConvAutoencoder, PaperArchitectureShapes) {
  const AutoencoderArchitecture a;  // the paper's defaults
  EXPECT_EQ(a.encoder_sizes(), (std::vector<int>{32, 32, 16, 16, 8}));
  nn::Rng init(1);
  ConvAutoencoder<float> model(a, init);
  EXPECT_EQ(model.image_values(), 3 * 64 * 64);
  const auto params = model.parameters();
  ASSERT_EQ(params.size(), 24u);  // 5 conv + 2 Linear + 5 transposed conv, weight and bias each
  EXPECT_EQ(params[0].name, "encoder.conv0.weight");
  EXPECT_EQ(params[0].shape, (std::vector<std::int64_t>{32, 3, 3, 3}));
  EXPECT_EQ(params[10].name, "encoder.fc.weight");
  EXPECT_EQ(params[10].shape, (std::vector<std::int64_t>{8, 4096}));
  EXPECT_EQ(params[12].shape, (std::vector<std::int64_t>{4096, 8}));
  EXPECT_EQ(params[14].name, "decoder.deconv4.weight");
  EXPECT_EQ(params.back().name, "decoder.deconv0.bias");
  EXPECT_EQ(params.back().shape, (std::vector<std::int64_t>{3}));
  EXPECT_EQ(nn::count_parameters(params), model.parameter_count());

  nn::Mat<float> images = nn::Mat<float>::Constant(2, model.image_values(), 0.5f);
  const nn::Mat<float> latents = model.encode(images);
  EXPECT_EQ(latents.rows(), 2);
  EXPECT_EQ(latents.cols(), 8);
  const nn::Mat<float> reconstruction = model.reconstruct(images);
  EXPECT_EQ(reconstruction.cols(), 3 * 64 * 64);
  EXPECT_GT(reconstruction.minCoeff(), 0.0f);  // sigmoid output
  EXPECT_LT(reconstruction.maxCoeff(), 1.0f);
  EXPECT_TRUE(model.decode(latents).isApprox(reconstruction));
}

TEST(ConvAutoencoder, InferenceInChunksMatchesOneBatch) {
  const AutoencoderArchitecture a = tiny_architecture(8);
  nn::Rng init(2);
  ConvAutoencoder<double> model(a, init);
  std::mt19937_64 rng(5);
  const nn::Index n = ConvAutoencoder<double>::kInferenceChunk + 5;
  const MatD images = random_images(n, model.image_values(), rng);
  const MatD latents = model.encode(images);
  for (nn::Index i : {nn::Index(0), n - 1}) {
    const MatD one = model.encode(images.middleRows(i, 1));
    EXPECT_LE((one - latents.middleRows(i, 1)).norm(), 1e-12);
  }
}

TEST(ConvAutoencoder, RejectsInvalidArchitectures) {
  nn::Rng init(1);
  AutoencoderArchitecture a = tiny_architecture(8);
  a.filters = {3};
  EXPECT_THROW({ ConvAutoencoder<float> model(a, init); }, std::invalid_argument);
  a = tiny_architecture(8);
  a.strides = {2, 0};
  EXPECT_THROW(a.validate(), std::invalid_argument);
  a = tiny_architecture(1);
  a.kernel_size = 4;  // padding 1: a 1x1 image is smaller than the kernel
  EXPECT_THROW(a.validate(), std::invalid_argument);
  AutoencoderArchitecture b = tiny_architecture(8);
  b.strides = {2, 2, 2};
  EXPECT_THAT([&] { b.validate(); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("3 strides but 2 filters")));
}

TEST(AutoencoderParams, DefaultsAreThePapersAndConfigIsStrict) {
  ConfigNode empty = ConfigNode::parse("{}", "ae.yaml");
  AutoencoderParams defaults;
  ConfigReader::read(empty, "context", defaults);
  EXPECT_EQ(defaults.architecture(), AutoencoderArchitecture{});
  EXPECT_DOUBLE_EQ(defaults.learning_rate, 3e-4);
  EXPECT_EQ(defaults.epochs, 70);
  EXPECT_DOUBLE_EQ(defaults.test_fraction, 0.1);

  ConfigNode small = ConfigNode::parse(
      "image_size: 16\nstrides: [2, 2]\nfilters: [8, 16]\nlatent_size: 4\nthreads: 1\n", "ae.yaml");
  AutoencoderParams p;
  ConfigReader::read(small, "context", p);
  EXPECT_EQ(p.strides, (std::vector<int>{2, 2}));
  EXPECT_EQ(p.architecture().encoder_sizes(), (std::vector<int>{8, 4}));

  ConfigNode bad_stride = ConfigNode::parse("strides: [2, 0]\n", "ae.yaml");
  EXPECT_THROW(ConfigReader::read(bad_stride, "context", p), ConfigError);
  ConfigNode typo = ConfigNode::parse("latnet_size: 4\n", "ae.yaml");
  EXPECT_THROW(ConfigReader::read(typo, "context", p), ConfigError);
}

std::string scratch_file(const std::string& name) { return ::testing::TempDir() + name; }

TEST(ConvAutoencoder, ModelFileRoundTripGivesIdenticalLatents) {
  AutoencoderArchitecture a = tiny_architecture(8);
  a.channels = 3;
  nn::Rng init(4);
  ConvAutoencoder<float> model(a, init);
  std::mt19937_64 rng(9);
  const nn::Mat<float> images = random_images(4, model.image_values(), rng).cast<float>();
  const std::string path = scratch_file("autoencoder_round_trip.cmpm");
  save_autoencoder(model, path);
  ConvAutoencoder<float> loaded = load_autoencoder(path);
  EXPECT_EQ(loaded.architecture(), a);
  EXPECT_EQ(loaded.encode(images), model.encode(images));
  EXPECT_EQ(loaded.reconstruct(images), model.reconstruct(images));
  std::remove(path.c_str());
}

TEST(ConvAutoencoder, ModelFileWithAnotherArchitectureOrModelIsRejected) {
  nn::Rng init(4);
  ConvAutoencoder<float> model(tiny_architecture(8), init);
  nn::ModelFile file;
  model.save_to(file);
  file.source = "ae.cmpm";

  AutoencoderArchitecture other = tiny_architecture(8);
  other.latent_size = 3;
  ConvAutoencoder<float> different(other, init);
  EXPECT_THAT(
      [&] { different.load_from(file); },
      ThrowsMessage<std::runtime_error>(AllOf(HasSubstr("model file 'ae.cmpm'"),
                                              HasSubstr("architecture"), HasSubstr("latent 3"))));

  file.hyper["model"] = "cnmp";
  EXPECT_THAT([&] { model.load_from(file); },
              ThrowsMessage<std::runtime_error>(
                  HasSubstr("holds model 'cnmp', expected 'conv_autoencoder'")));
}

TEST(AutoencoderImages, RoundTripAndLayout) {
  const cv::Mat image = testing::square_image(3.5, 16, 5);
  const nn::ImageShape shape{3, 16, 16};
  const nn::Mat<float> batch = images_to_batch({image, image}, shape);
  ASSERT_EQ(batch.rows(), 2);
  // Channel-major layout: R plane first. Pixel (8, 5) is inside the red square.
  const cv::Vec3b pixel = image.at<cv::Vec3b>(8, 5);
  EXPECT_FLOAT_EQ(batch(0, 8 * 16 + 5), pixel[0] / 255.0f);
  EXPECT_FLOAT_EQ(batch(0, 256 + 8 * 16 + 5), pixel[1] / 255.0f);
  EXPECT_FLOAT_EQ(batch(0, 512 + 8 * 16 + 5), pixel[2] / 255.0f);
  const std::vector<cv::Mat> back = batch_to_images(batch, shape);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(cv::norm(back[1], image, cv::NORM_INF), 0.0);
}

TEST(AutoencoderImages, ResizesWithAreaAveragingAndChecksChannels) {
  cv::Mat big(32, 32, CV_8UC3, cv::Scalar(10, 20, 30));
  big(cv::Rect(0, 0, 2, 2)).setTo(cv::Scalar(50, 60, 70));  // one 2x2 block -> pixel (0, 0)
  const nn::Mat<float> batch = images_to_batch({big}, {3, 16, 16});
  EXPECT_FLOAT_EQ(batch(0, 0), 50 / 255.0f);
  EXPECT_FLOAT_EQ(batch(0, 1), 10 / 255.0f);
  EXPECT_FLOAT_EQ(batch(0, 256 + 17), 20 / 255.0f);

  const cv::Mat grey(16, 16, CV_8UC1, cv::Scalar(7));
  EXPECT_THROW(images_to_batch({grey}, {3, 16, 16}), std::invalid_argument);
  EXPECT_FLOAT_EQ(images_to_batch({grey}, {1, 16, 16})(0, 3), 7 / 255.0f);
  const cv::Mat floats(16, 16, CV_32FC3);
  EXPECT_THROW(images_to_batch({floats}, {3, 16, 16}), std::invalid_argument);
}

}  // namespace
}  // namespace corrmp
