// The matrix products of the convolution layers (nn/conv2d.hpp, nn/conv_transpose2d.hpp,
// nn/winograd_conv3x3.hpp) and of the fully connected layers (nn/linear.hpp): C = op(A) op(B),
// or C += op(A) op(B), on row-major views, op(X) being X or X^T.
//
// Why not Eigen or a BLAS: the autoencoder's products are small in at least one dimension
// (K = Cin k k of im2col or Cin of a Winograd term, or M, N = channels) and run thousands of
// times per step; Eigen repacks both operands on every call, and Debian's OpenBLAS does not pick
// its AVX-512 kernels on every AVX-512 machine, so both were slower on these shapes
// (docs/performance.md, "Measurements behind the code"). The float products run here when the
// compiler targets AVX-512 (the build uses -march=native); everything else (double, used by the
// gradient checks, and float without AVX-512) runs Eigen's products.
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
