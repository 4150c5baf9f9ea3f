// Bounds on config input, so that a hostile or broken config file fails with a
// one-line ConfigError instead of exhausting memory, time or the stack.
// docs/architecture.md, "Configs".
#pragma once

#include <cstddef>
#include <string>

namespace corrmp {

// One config file (or one command-line override).
constexpr std::size_t kMaxConfigFileBytes = std::size_t{1} << 20;  // 1 MiB
// A config and every file it includes, read in total.
constexpr std::size_t kMaxConfigTotalBytes = std::size_t{8} << 20;  // 8 MiB
// Values (scalars, lists, maps, nulls) in a config with its includes and
// overrides, counting each alias expansion.
constexpr std::size_t kMaxConfigNodes = 100000;
// Nesting of lists and maps, the document root being level 1.
constexpr int kMaxConfigDepth = 64;
// Files included within files included within ... the config.
constexpr int kMaxIncludeDepth = 16;

// What is left of the bounds while one config (its includes and overrides) is
// loaded. A fresh budget allows everything up to the limits above.
struct ConfigBudget {
  std::size_t nodes_left = kMaxConfigNodes;
  std::size_t bytes_left = kMaxConfigTotalBytes;
};

// "1 MiB", "8 MiB": how the limits are stated in messages.
inline std::string describe_bytes(std::size_t bytes) {
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  if (bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace corrmp
