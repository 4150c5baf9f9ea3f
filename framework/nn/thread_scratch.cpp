// Per-thread scratch buffers of the convolution layers (nn/thread_scratch.hpp).
#include "nn/thread_scratch.hpp"

namespace corrmp::nn {

template <class S>
Buffer<S>& thread_scratch(Scratch slot) {
  thread_local Buffer<S> buffers[static_cast<int>(Scratch::kCount)];
  return buffers[static_cast<int>(slot)];
}

template Buffer<float>& thread_scratch<float>(Scratch);
template Buffer<double>& thread_scratch<double>(Scratch);

}  // namespace corrmp::nn
