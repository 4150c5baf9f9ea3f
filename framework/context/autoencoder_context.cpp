// The autoencoder context: training (or reuse), encoding, figures.
#include "context/autoencoder_context.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "context/autoencoder/autoencoder_figures.hpp"
#include "context/autoencoder/autoencoder_images.hpp"
#include "context/autoencoder/autoencoder_trainer.hpp"
#include "core/config/config_node.hpp"
#include "core/config/config_reader.hpp"
#include "core/file_lock.hpp"
#include "core/parameter_error.hpp"

namespace corrmp {

namespace {

// The parameters as canonical text, part of the cache key.
std::string params_text(const AutoencoderParams& params) {
  ConfigNode node = ConfigNode::map(SourceLocation{});
  AutoencoderParams copy = params;
  ConfigReader::read(node, "", copy);
  return node.to_yaml_string();
}

}  // namespace

AutoencoderContext::AutoencoderContext(const AutoencoderContextParams& params, uint64_t seed)
    : params_(params), seed_(seed) {
  params_.network.architecture().validate();
  if (params_.network.channels == 2) {
    throw ParameterError("network.channels", "must be 3 (RGB) or 1 (grey), not 2");
  }
}

std::vector<MemoryNeed> AutoencoderContext::memory_needs() const {
  return {{params_.network.training_bytes(), "network.batch_size",
           fmt::format("training the autoencoder ({}, batch_size {})",
                       params_.network.architecture().summary(), params_.network.batch_size)}};
}

AutoencoderContext::~AutoencoderContext() = default;

bool AutoencoderContext::wanted(const std::string& segment) const {
  return std::find(params_.segments.begin(), params_.segments.end(), segment) !=
         params_.segments.end();
}

void AutoencoderContext::fit(const std::vector<Demonstration>& demos, const ExtractorCache& cache,
                             Rng& rng) {
  std::vector<cv::Mat> images;
  for (const auto& demo : demos) {
    for (const auto& segment : demo.segments) {
      if (!wanted(segment.segment)) continue;
      if (segment.start.rgb.empty()) {
        throw std::runtime_error(fmt::format(
            "the autoencoder context needs camera images at the start of segment '{}': set "
            "demonstrations.images: true",
            segment.segment));
      }
      images.push_back(segment.start.rgb);
    }
  }
  if (images.empty()) throw std::runtime_error("no images to train the autoencoder on");
  const TrainTestSplit split =
      split_train_test(static_cast<int>(images.size()), params_.network.test_fraction, rng);
  std::vector<cv::Mat> train, test;
  for (int i : split.train) train.push_back(images[i]);
  for (int i : split.test) test.push_back(images[i]);
  test_images_ = test;

  const std::string key = fmt::format(
      "{:016x}",
      fnv1a64(fmt::format("v1 {} {} {}", seed_, cache.data_key, params_text(params_.network))));
  const std::string path =
      cache.directory.empty() ? "" : cache.directory + "/autoencoder-" + key + ".cmpm";
  model_.reset();
  // Concurrent runs (a sweep's jobs) wanting the same model: one trains it,
  // the others wait for it and reuse it.
  std::optional<FileLock> lock;
  if (!path.empty()) lock.emplace(path + ".lock");
  // A cached model that cannot be used (damaged, truncated, a directory in
  // its place) is reported once and trained again, never fatal.
  std::error_code error;
  if (!path.empty() && cache.reuse &&
      std::filesystem::symlink_status(path, error).type() !=
          std::filesystem::file_type::not_found) {
    try {
      model_ = std::make_unique<ConvAutoencoder<float>>(load_autoencoder(path));
      spdlog::info("reusing the trained autoencoder {}", path);
    } catch (const std::exception& e) {
      spdlog::warn("{}; training the autoencoder again", e.what());
    }
  }
  if (!model_) {
    nn::Rng init(seed_);
    model_ = std::make_unique<ConvAutoencoder<float>>(params_.network.architecture(), init);
    spdlog::info("training the autoencoder ({}) on {} images, {} held out",
                 params_.network.architecture().summary(), train.size(), test.size());
    const AutoencoderReport report = train_autoencoder(*model_, train, test, params_.network, rng);
    spdlog::info("autoencoder: train MSE {:.3g}, test MSE {:.3g}, {:.1f} s", report.train_mse,
                 report.test_mse, report.seconds);
    if (!path.empty()) {
      try {
        std::filesystem::create_directories(cache.directory);
        save_autoencoder(*model_, path);
      } catch (const std::exception& e) {  // the cache only saves time
        spdlog::warn("{}; the trained autoencoder is not cached", e.what());
      }
    }
  }
  lock.reset();
  const nn::Mat<float> train_batch = images_to_batch(train, model_->image_shape());
  train_mse_ = model_->reconstruction_mse(train_batch);
  if (!test.empty()) {
    test_mse_ = model_->reconstruction_mse(images_to_batch(test, model_->image_shape()));
  }
}

Eigen::VectorXd AutoencoderContext::extract(const std::string& segment,
                                            const Observation& observation) {
  if (!wanted(segment)) return Eigen::VectorXd();
  if (!model_) throw std::logic_error("the autoencoder context was not fitted");
  if (observation.rgb.empty()) {
    throw std::runtime_error(
        fmt::format("the autoencoder context of segment '{}' needs a camera image", segment));
  }
  return encode_images(*model_, {observation.rgb}).row(0).transpose();
}

void AutoencoderContext::write_outputs(const std::string& directory,
                                       const std::vector<Demonstration>& demos) {
  if (!model_) return;
  std::filesystem::create_directories(directory);
  save_autoencoder(*model_, directory + "/autoencoder.cmpm");
  if (!test_images_.empty()) {
    const size_t shown = std::min<size_t>(test_images_.size(), 16);
    const std::vector<cv::Mat> originals(test_images_.begin(), test_images_.begin() + shown);
    write_reconstruction_grid(originals, reconstruct_images(*model_, originals),
                              directory + "/autoencoder_reconstructions.png");
  }
  if (params_.plot_state.empty()) return;
  std::vector<double> x;
  std::vector<cv::Mat> images;
  for (const auto& demo : demos) {
    for (const auto& segment : demo.segments) {
      if (!wanted(segment.segment) || segment.start.rgb.empty()) continue;
      const auto it = segment.start.state.find(params_.plot_state);
      if (it == segment.start.state.end()) continue;
      x.push_back(it->second);
      images.push_back(segment.start.rgb);
    }
  }
  if (!images.empty()) {
    write_latent_plot(x, encode_images(*model_, images), params_.plot_state,
                      directory + "/autoencoder_latents.png");
  }
}

std::vector<std::string> AutoencoderContext::state_names() const {
  if (params_.plot_state.empty()) return {};
  return {params_.plot_state};
}

std::vector<Metric> AutoencoderContext::metrics() const {
  std::vector<Metric> out;
  // Of the images' pixel values, which have no unit.
  if (train_mse_ >= 0) out.push_back({"autoencoder_train_mse", train_mse_, error_metric("")});
  if (test_mse_ >= 0) out.push_back({"autoencoder_test_mse", test_mse_, error_metric("")});
  return out;
}

}  // namespace corrmp
