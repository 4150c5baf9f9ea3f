// Assigning contexts to demonstrations.
#include "context/context_extractor.hpp"

namespace corrmp {

void assign_contexts(ContextExtractor& extractor, std::vector<Demonstration>& demos) {
  for (auto& demo : demos) {
    for (auto& segment : demo.segments) {
      segment.context = extractor.extract(segment.segment, segment.start);
    }
  }
}

}  // namespace corrmp
