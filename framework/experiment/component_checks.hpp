// Load-time checks across components: what a config asks of one component
// must be something another provides, so a mismatch is a config error (exit 2)
// before any run is recorded, never a failure after training
// (docs/architecture.md, "Load-time checks"):
// - every segment the policy learns from is one the demonstrations hold;
// - every segment the policy conditions on a context gets one, from the
//   context extractor or from the demonstrations themselves;
// - every segment the extractor gives a context for exists;
// - an expert demonstrates in the environment it was made for;
// - an extractor that reads images gets demonstrations that record them;
// - the state values an extractor reads are ones the environment observes;
// - an evaluation in an environment has an expert that can demonstrate.
#pragma once

#include "experiment/experiment.hpp"

namespace corrmp {

// Throws ConfigError naming the file, line and key path of the offending value.
void check_components(const Experiment& experiment);

}  // namespace corrmp
