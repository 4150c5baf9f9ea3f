// What a component's declared sizes will take in memory, estimated at load so that absurd but
// in-range sizes (a batch of 2e9, an image of 100000 pixels a side) are refused with the key to
// change before a run starts, instead of exhausting memory mid-run. docs/architecture.md,
// "Configs".
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace corrmp {

struct MemoryNeed {
  double bytes = 0.0;  // an estimate of the peak, in bytes
  std::string key;     // the parameter that drives it, relative to the component's section
  std::string what;    // "CNMP training batches (batch_size 8 x 15 points x ...)"
};

// "1.5 GiB", "300 MiB", "12 KiB".
std::string format_bytes(double bytes);

// The machine's physical memory in bytes (0 when unknown).
double physical_memory_bytes();

// The memory this process may use: the machine's, or less when a limit on the process's
// address space or data (ulimit -v, -d) is lower. `bytes` is 0 when unknown.
struct MemoryBudget {
  double bytes = 0.0;
  bool limited = false;  // set by a process limit, not by the machine's memory
};
MemoryBudget usable_memory();

// The share of the usable memory that declared sizes may plan to take.
constexpr double kMemoryShare = 0.75;

// The index of the largest of `needs` when together they exceed kMemoryShare of `budget`;
// nothing when they fit or the budget is unknown.
std::optional<size_t> largest_need_beyond(const std::vector<MemoryNeed>& needs,
                                          const MemoryBudget& budget);

// "the declared sizes need about 24.0 GiB of memory, 23.5 GiB of it for <what of the largest>;
// this machine has 23.4 GiB: reduce them" (or "this process may use 7.6 GiB (ulimit)").
std::string memory_refusal(const std::vector<MemoryNeed>& needs, size_t largest,
                           const MemoryBudget& budget);

}  // namespace corrmp
