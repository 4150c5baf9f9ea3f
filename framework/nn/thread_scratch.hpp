// Scratch buffers that the convolution layers share, one set per thread (the autoencoder of
// paper Section III "Learning the Context"; data-parallel training in
// context/autoencoder/data_parallel_trainer.hpp).
//
// A convolution's call fills chunk-sized matrices (the Winograd term matrices of
// nn/winograd_conv3x3.hpp and nn/winograd_stride2_conv3x3.hpp, their summed weight terms) that
// are dead once the call returns. When every layer kept its own, the paper's network held about
// 8 MB of them per data-parallel replica, and a training step on two replicas touched about 45 MB
// in all, more than the 32 MB L3 cache of the machine the speed goals were set on: each layer's
// writes went to lines of its own that had long left the caches. Shared, a layer writes to the
// lines the previous layer has just used, still in the core's L2 cache. Measured on that machine
// (2-core Zen 4 EPYC, bench_autoencoder, batch 16, 2 threads, alternated runs of the builds
// before and after): 862 -> 950 images/s (median of 16 pairs; 14 of 16 won). docs/performance.md
// keeps the measurement.
//
// Rules for a user: a slot's contents are valid only within one call of one layer (the call
// sizes it with Buffer::resize and must not expect anything from an earlier call), and a
// function using a slot calls nothing that uses the same slot while its contents are needed.
// Threads never share a slot, so layers of different models may run on different threads at
// once, as before.
#pragma once

#include "nn/buffer.hpp"

namespace corrmp::nn {

/// The shared buffers. (nn/gemm.hpp's operand copy has its own: gemm_scratch.)
enum class Scratch {
  kInputTerms,   ///< the input side's term matrices of one chunk (V, then dV)
  kOutputTerms,  ///< the output side's (M or dM)
  kWeightTerms,  ///< the weight terms' gradients summed over a batch (dU)
  kCount,
};

/// This thread's buffer for `slot`; grown on first use, then reused.
template <class S>
Buffer<S>& thread_scratch(Scratch slot);

extern template Buffer<float>& thread_scratch<float>(Scratch);
extern template Buffer<double>& thread_scratch<double>(Scratch);

}  // namespace corrmp::nn
