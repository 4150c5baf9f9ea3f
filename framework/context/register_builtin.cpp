// Registration of the context module's extractors.
#include "context/register_builtin.hpp"

#include "context/perfect_context.hpp"

namespace corrmp {

void register_builtin_contexts(Registry<ContextExtractor>& contexts) {
  contexts.add<PerfectContextParams>(
      "perfect", "named simulator state values (corridor x, object x, ...) as the context",
      [](const PerfectContextParams& p, const BuildContext&) { return new PerfectContext(p); });
}

}  // namespace corrmp
