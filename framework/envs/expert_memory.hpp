// What an emulated expert's demonstrations will take in memory with the
// declared sizes, estimated at load (docs/architecture.md, "Configs"): the
// segment trajectories and the whole skill's, from the environment's segment
// lengths, and the camera images recorded at segment starts, from its camera
// size. A task's expert passes how many demonstrations and images it records.
#pragma once

#include <cstdint>
#include <vector>

#include "core/memory_need.hpp"

namespace corrmp {

class Environment;

struct ExpertRecording {
  int demonstrations = 0;            // training and validation
  int images_per_demonstration = 0;  // 0 when the expert takes no images
};

// Nothing (0) without an environment: the expert is then refused for that.
std::vector<MemoryNeed> expert_memory_needs(const Environment* environment,
                                            const ExpertRecording& recording);

// The whole skill's trajectory, every segment's points: the longest an expert records.
int64_t expert_longest_trajectory(const Environment* environment);

}  // namespace corrmp
