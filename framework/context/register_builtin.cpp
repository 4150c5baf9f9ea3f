// Registration of the context module's extractors.
#include "context/register_builtin.hpp"

#include "context/autoencoder_context.hpp"
#include "context/perfect_context.hpp"

namespace corrmp {

void register_builtin_contexts(Registry<ContextExtractor>& contexts) {
  contexts.add<PerfectContextParams>(
      "perfect", "named simulator state values (corridor x, object x, ...) as the context",
      [](const PerfectContextParams& p, const BuildContext&) { return new PerfectContext(p); });
  contexts.add<AutoencoderContextParams>(
      "autoencoder", "latent of a convolutional autoencoder of the head-camera image (paper III-B)",
      [](const AutoencoderContextParams& p, const BuildContext& context) {
        return new AutoencoderContext(p, context.seeds.seed_for("context.init"));
      });
}

}  // namespace corrmp
