// What a component's declared sizes will take in memory, estimated at load so that absurd but
// in-range sizes (a batch of 2e9, an image of 100000 pixels a side) are refused with the key to
// change before a run starts, instead of exhausting memory mid-run. docs/architecture.md,
// "Configs".
#pragma once

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

}  // namespace corrmp
