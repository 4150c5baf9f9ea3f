// Context extractor `autoencoder` (paper, Section III-B "Learning the
// Context"): a convolutional autoencoder compresses the head-camera image, and
// its latent vector is the context: cor-MP gets the latent of the image taken
// after pre-MP, post-MP the latent of the image taken after cor-MP (the images
// at those segments' starts). The trained autoencoder is cached in a model file
// keyed by its parameters and its images, and reused when neither changed.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "context/autoencoder/autoencoder_params.hpp"
#include "context/autoencoder/conv_autoencoder.hpp"
#include "context/context_extractor.hpp"

namespace corrmp {

struct AutoencoderContextParams {
  std::vector<std::string> segments{"cor", "post"};
  AutoencoderParams network;
  std::string plot_state;

  template <class Fields>
  void describe(Fields& f) {
    f("segments", segments, "segments whose context is the latent of their start image");
    f("network", network, "the autoencoder and its training (the paper's values by default)");
    f("plot_state", plot_state,
      "state value the latent plot puts on its x axis ('' : no latent plot)");
  }
};

class AutoencoderContext : public ContextExtractor {
 public:
  AutoencoderContext(const AutoencoderContextParams& params, uint64_t seed);
  ~AutoencoderContext() override;

  void fit(const std::vector<Demonstration>& demos, const ExtractorCache& cache, Rng& rng) override;
  Eigen::VectorXd extract(const std::string& segment, const Observation& observation) override;
  std::vector<std::string> segments() const override { return params_.segments; }
  std::vector<std::string> state_names() const override;
  bool needs_images() const override { return true; }
  std::vector<MemoryNeed> memory_needs() const override;
  void write_outputs(const std::string& directory,
                     const std::vector<Demonstration>& demos) override;
  std::vector<Metric> metrics() const override;

 private:
  bool wanted(const std::string& segment) const;

  AutoencoderContextParams params_;
  uint64_t seed_;
  std::unique_ptr<ConvAutoencoder<float>> model_;
  std::vector<cv::Mat> test_images_;
  double test_mse_ = -1.0;
  double train_mse_ = -1.0;
};

}  // namespace corrmp
