// Demonstration sources: the default for sources that are not experts.
#include "envs/demonstration_source.hpp"

#include <stdexcept>

namespace corrmp {

Demonstration DemonstrationSource::demonstrate(Environment&, const Scenario&, bool) {
  throw std::logic_error(
      "this demonstration source cannot demonstrate a given scenario (can_demonstrate() is false; "
      "the experiment loader checks it)");
}

}  // namespace corrmp
