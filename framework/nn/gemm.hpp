// The matrix products of the convolution layers (nn/conv2d.hpp, nn/conv_transpose2d.hpp,
// nn/winograd_conv3x3.hpp) and of the fully connected layers (nn/linear.hpp): C = op(A) op(B),
// or C += op(A) op(B), on row-major views, op(X) being X or X^T.
//
// The CNMP's layers (40-80 rows of width 128 per step) gain too: on one core of a Zen 4 EPYC
// (medians of 5), bench_cnmp's BM_update_defaults_b8_targets10 went from 3,030 to 3,600
// updates/s and BM_update_b32 from 1,960 to 2,540 when Linear moved from Eigen's products to
// this kernel.
//
// Why not Eigen or a BLAS: the autoencoder's products are small in at least one dimension
// (K = Cin k k of im2col or Cin of a Winograd term, or M, N = channels) and run thousands of
// times per step, and they were 56% of a training step. Measured on this project's machine
// (AMD EPYC, Zen 5 with AVX-512, one core, the 20 product shapes of a 16-image shard of the
// paper's architecture, hot caches): Eigen 3.4 reaches 105-165 GFLOP/s (its float kernel is
// 48x4 with AVX-512 and it repacks both operands on every call); Debian 12's OpenBLAS 0.3.21
// (libopenblas0-serial, cblas_sgemm) reaches 60-115 GFLOP/s, because its run-time CPU detection
// does not know Zen 5 and selects its AVX2 Haswell kernels (forced to its AVX-512 kernels with
// OPENBLAS_CORETYPE=SkylakeX it would reach 125-230, but that variable must be set before the
// program starts, and is a per-machine setting the program cannot own); the kernel below reaches
// 150-245 GFLOP/s: 13.8 ms per shard against Eigen's 20.5 ms and OpenBLAS's 29.8 ms. So the float
// products run here when the compiler targets AVX-512 (the build uses -march=native), and
// everything else (double, used by the gradient checks, and float without AVX-512) runs the same
// Eigen products as before.
//
// The kernel keeps an 8 x 32 block of C in 16 AVX-512 registers and adds, for each p < K, row p
// of op(B)'s 32 columns (two vector loads) times each of the block's 8 entries of column p of
// op(A) (broadcasts straight from A, whichever its layout), so neither operand is packed when
// op(B) = B. When op(B) = B^T, B is first transposed into `scratch` (K x N rounded up to 16),
// the one copy the kernel needs. Each C entry is the sum over p = 0, 1, ..., K - 1 in that order
// (fused multiply-adds from zero), then added to C with accumulate: the result depends only on
// the operands, never on how a caller splits its work among threads.
#pragma once

#include "nn/buffer.hpp"
#include "nn/tensor.hpp"

namespace corrmp::nn {

/// How a gemm operand enters the product.
enum class Op { kPlain, kTransposed };

/// c = op_a(a) op_b(b), or c += op_a(a) op_b(b) with accumulate. All views are row-major with
/// unit inner stride (Maps, blocks and matrices bind without a copy), and c overlaps neither a
/// nor b; `scratch` holds the transposed b when op_b is kTransposed (grown on first use, then
/// reused). Throws std::invalid_argument when the shapes do not match.
template <class S>
void gemm(ConstMatRef<S> a, Op op_a, ConstMatRef<S> b, Op op_b, MatRef<S> c, bool accumulate,
          Buffer<S>& scratch);

/// True when float products run on the kernel above, whose every entry of C is the same whatever
/// block of C a call computes (so work cut among threads keeps its bits, nn/team.hpp); Eigen's
/// products, used otherwise, group their sums by block position.
bool gemm_float_split_exact();

/// A scratch buffer for gemm, one per thread (nn/thread_scratch.hpp's kGemmOperand): layers that
/// run on several threads at once (a model predicting in several evaluation trials, a team's
/// members) keep none of their own.
template <class S>
Buffer<S>& gemm_scratch();

extern template void gemm<float>(ConstMatRef<float>, Op, ConstMatRef<float>, Op, MatRef<float>,
                                 bool, Buffer<float>&);
extern template void gemm<double>(ConstMatRef<double>, Op, ConstMatRef<double>, Op, MatRef<double>,
                                  bool, Buffer<double>&);
extern template Buffer<float>& gemm_scratch<float>();
extern template Buffer<double>& gemm_scratch<double>();

}  // namespace corrmp::nn
