// Registration of the context module's extractors.
#pragma once

#include "context/context_extractor.hpp"
#include "core/registry.hpp"

namespace corrmp {

void register_builtin_contexts(Registry<ContextExtractor>& contexts);

}  // namespace corrmp
