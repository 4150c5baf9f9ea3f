// What training a CNMP will take in memory, estimated from its sizes before anything is
// allocated, so that run_experiment (at load) and train_cnmp (before training) refuse sizes that
// cannot fit, naming the one to change (core/memory_need.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "cnmp/cnmp_architecture.hpp"
#include "cnmp/cnmp_trainer.hpp"
#include "core/memory_need.hpp"

namespace corrmp {

// The key of each need, relative to a policy's section.
inline constexpr const char* kNetworkKey = "network.width";
inline constexpr const char* kBatchKey = "training.batch_size";

// Peak memory of training one CNMP, in two needs: the network (kNetworkKey: its weights with
// their gradients, Adam's moments and the copies training and saving make) and the batches
// (kBatchKey: activations and their gradients). `longest` is the longest trajectory when known
// (it caps the points per demonstration), else 0.
std::vector<MemoryNeed> cnmp_training_needs(const CnmpArchitecture& architecture,
                                            const CnmpTrainingParams& params, int64_t longest);

}  // namespace corrmp
