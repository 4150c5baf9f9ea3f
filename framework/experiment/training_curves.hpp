// The training curves of a run's networks (loss and validation error against
// updates), written to <run dir>/training_curves.csv for plotting and for the
// reproduction report's figure (docs/sweeps.md).
#pragma once

#include <string>
#include <vector>

#include "policies/policy.hpp"

namespace corrmp {

// Columns: network, update, loss, validation_error_mean, validation_error_max
// (empty where there was no validation data).
void write_training_curves(const std::vector<PolicyTrainingSummary>& summaries,
                           const std::string& path);

}  // namespace corrmp
