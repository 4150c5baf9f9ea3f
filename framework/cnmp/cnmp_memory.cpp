// Memory estimates of CNMP training (cnmp_memory.hpp).
#include "cnmp/cnmp_memory.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace corrmp {

namespace {

// Seven float copies of the parameters while training: the weights, their gradients, Adam's
// two moments, the best weights kept, and the copy that validates beside the training (weights
// and gradients). Measured: 24-25 bytes per parameter of peak resident memory at widths 512 to
// 2048 with 16 + 16 layers, in train_cnmp and in run_experiment.
constexpr double kBytesPerParameter = 7.0 * sizeof(float);

}  // namespace

std::vector<MemoryNeed> cnmp_training_needs(const CnmpArchitecture& architecture,
                                            const CnmpTrainingParams& params, int64_t longest) {
  const double batch = params.batch_size;
  const double observations = longest > 1 ? std::min<double>(params.max_observations, longest - 1)
                                          : params.max_observations;
  const double targets =
      longest > 0 ? std::min<double>(params.max_targets, longest) : params.max_targets;
  const double rows =
      batch * (observations * architecture.encoder_layers + targets * architecture.decoder_layers);
  const double activations = 3.0 * rows * architecture.width * sizeof(float);
  const int64_t parameters = cnmp_parameter_count(architecture);
  return {
      {static_cast<double>(parameters) * kBytesPerParameter, kNetworkKey,
       fmt::format("the network ({} parameters: width {}, {} encoder and {} decoder layers)",
                   parameters, architecture.width, architecture.encoder_layers,
                   architecture.decoder_layers)},
      {activations, kBatchKey,
       fmt::format("the training batches (batch_size {}, max_observations {}, max_targets {}, "
                   "width {})",
                   params.batch_size, params.max_observations, params.max_targets,
                   architecture.width)},
  };
}

}  // namespace corrmp
