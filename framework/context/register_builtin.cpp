// Registration of the context module's extractors.
#include "context/register_builtin.hpp"

#include <memory>

#include "context/autoencoder_context.hpp"
#include "context/color_segmentation_context.hpp"
#include "context/perfect_context.hpp"

namespace corrmp {

void register_builtin_contexts(Registry<ContextExtractor>& contexts) {
  contexts.add<PerfectContextParams>(
      "perfect", "named simulator state values (an object's x, ...) as the context",
      [](const PerfectContextParams& p, const SeedTree&) {
        return std::make_unique<PerfectContext>(p);
      });
  contexts.add<AutoencoderContextParams>(
      "autoencoder", "latent of a convolutional autoencoder of the head-camera image (paper III-B)",
      [](const AutoencoderContextParams& p, const SeedTree& seeds) {
        return std::make_unique<AutoencoderContext>(p, seeds.seed_for("context.init"));
      });
  contexts.add<ColorSegmentationContextParams>(
      "color_segmentation",
      "a coloured object found by colour segmentation of the RGB-D head camera, relative to the "
      "gripper mid-point (paper IV-C)",
      [](const ColorSegmentationContextParams& p, const SeedTree& seeds) {
        return std::make_unique<ColorSegmentationContext>(p, seeds.seed_for("context.noise"));
      });
}

}  // namespace corrmp
