// Matrix products of the convolution layers: an AVX-512 float kernel, Eigen otherwise (why and
// how in nn/gemm.hpp).
#include "nn/gemm.hpp"

#include <algorithm>
#include <type_traits>

#include "nn/check.hpp"
#include "nn/thread_scratch.hpp"
#include "nn/transpose.hpp"

#if defined(__AVX512F__)
#include <immintrin.h>
#define CORRMP_GEMM_AVX512 1
#else
#define CORRMP_GEMM_AVX512 0
#endif

namespace corrmp::nn {
namespace {

// The products as Eigen computes them.
template <class S>
void eigen_gemm(ConstMatRef<S> a, Op op_a, ConstMatRef<S> b, Op op_b, MatRef<S> c,
                bool accumulate) {
  const auto product = [&](const auto& x, const auto& y) {
    if (accumulate)
      c.noalias() += x * y;
    else
      c.noalias() = x * y;
  };
  if (op_a == Op::kPlain && op_b == Op::kPlain)
    product(a, b);
  else if (op_a == Op::kPlain)
    product(a, b.transpose());
  else if (op_b == Op::kPlain)
    product(a.transpose(), b);
  else
    product(a.transpose(), b.transpose());
}

#if CORRMP_GEMM_AVX512

constexpr int kLanes = 16;  // floats per AVX-512 register
constexpr int kRows = 8;    // rows of C per kernel call (kRows x kVectors accumulators)
constexpr int kVectors = 2;

// The operand A of the kernel: op(A)[i][p] is data[i * stride + p] (kTransposedA false) or
// data[p * stride + i] (true).
struct Lhs {
  const float* data;
  Index stride;
};

template <bool kTransposedA>
const float* lhs_row(const Lhs& a, Index i) {
  return kTransposedA ? a.data + i : a.data + i * a.stride;
}

// Rows [0, R), columns [0, 16 V) of C: c[i][.] (+)= sum over p < k of op(A)[i][p] B[p][.], B's
// rows ldb apart, the last vector of columns limited to the lanes in `last`. The loops over the
// block are unrolled so that the accumulators stay in registers.
template <int R, int V, bool kTransposedA>
void kernel(Index k, const Lhs& a, const float* __restrict b, Index ldb, float* __restrict c,
            Index ldc, bool accumulate, __mmask16 last) {
  __m512 acc[R][V];
#pragma GCC unroll 16
  for (int i = 0; i < R; ++i)
#pragma GCC unroll 4
    for (int v = 0; v < V; ++v) acc[i][v] = _mm512_setzero_ps();
  const float* __restrict rows[R];  // for kTransposedA false
#pragma GCC unroll 16
  for (int i = 0; i < R; ++i) rows[i] = a.data + i * a.stride;
#pragma GCC unroll 2
  for (Index p = 0; p < k; ++p) {
    __m512 bv[V];
#pragma GCC unroll 4
    for (int v = 0; v < V; ++v)
      bv[v] = v + 1 < V ? _mm512_loadu_ps(b + p * ldb + kLanes * v)
                        : _mm512_maskz_loadu_ps(last, b + p * ldb + kLanes * v);
#pragma GCC unroll 16
    for (int i = 0; i < R; ++i) {
      const __m512 ai = _mm512_set1_ps(kTransposedA ? a.data[p * a.stride + i] : rows[i][p]);
#pragma GCC unroll 4
      for (int v = 0; v < V; ++v) acc[i][v] = _mm512_fmadd_ps(ai, bv[v], acc[i][v]);
    }
  }
#pragma GCC unroll 16
  for (int i = 0; i < R; ++i)
#pragma GCC unroll 4
    for (int v = 0; v < V; ++v) {
      float* out = c + i * ldc + kLanes * v;
      const __mmask16 mask = v + 1 < V ? __mmask16(0xFFFF) : last;
      __m512 sum = acc[i][v];
      if (accumulate) sum = _mm512_add_ps(_mm512_maskz_loadu_ps(mask, out), sum);
      _mm512_mask_storeu_ps(out, mask, sum);
    }
}

// All m rows of C for one strip of 16 V columns: kRows at a time, then the remaining rows.
template <int V, bool kTransposedA>
void strip(Index m, Index k, const Lhs& a, const float* b, Index ldb, float* c, Index ldc,
           bool accumulate, __mmask16 last) {
  Index i = 0;
  for (; i + kRows <= m; i += kRows)
    kernel<kRows, V, kTransposedA>(k, Lhs{lhs_row<kTransposedA>(a, i), a.stride}, b, ldb,
                                   c + i * ldc, ldc, accumulate, last);
  const Lhs rest{lhs_row<kTransposedA>(a, i), a.stride};
  float* c_rest = c + i * ldc;
  static_assert(kRows == 8, "the remainder cases below cover 1 .. kRows - 1 rows");
  switch (m - i) {
    case 1:
      kernel<1, V, kTransposedA>(k, rest, b, ldb, c_rest, ldc, accumulate, last);
      break;
    case 2:
      kernel<2, V, kTransposedA>(k, rest, b, ldb, c_rest, ldc, accumulate, last);
      break;
    case 3:
      kernel<3, V, kTransposedA>(k, rest, b, ldb, c_rest, ldc, accumulate, last);
      break;
    case 4:
      kernel<4, V, kTransposedA>(k, rest, b, ldb, c_rest, ldc, accumulate, last);
      break;
    case 5:
      kernel<5, V, kTransposedA>(k, rest, b, ldb, c_rest, ldc, accumulate, last);
      break;
    case 6:
      kernel<6, V, kTransposedA>(k, rest, b, ldb, c_rest, ldc, accumulate, last);
      break;
    case 7:
      kernel<7, V, kTransposedA>(k, rest, b, ldb, c_rest, ldc, accumulate, last);
      break;
    default:
      break;
  }
}

// C (m x n) (+)= op(A) B with B row-major k x n: strips of 32 columns, then one of 16 or 32
// with its last vector masked.
template <bool kTransposedA>
void product(Index m, Index n, Index k, const Lhs& a, const float* b, Index ldb, float* c,
             Index ldc, bool accumulate) {
  constexpr Index kStrip = kLanes * kVectors;
  Index j = 0;
  for (; j + kStrip <= n; j += kStrip)
    strip<kVectors, kTransposedA>(m, k, a, b + j, ldb, c + j, ldc, accumulate, 0xFFFF);
  const Index rest = n - j;
  if (rest == 0) return;
  const int tail = static_cast<int>(rest % kLanes);
  const __mmask16 last = tail == 0 ? __mmask16(0xFFFF) : __mmask16((1u << tail) - 1);
  if (rest > kLanes)
    strip<2, kTransposedA>(m, k, a, b + j, ldb, c + j, ldc, accumulate, last);
  else
    strip<1, kTransposedA>(m, k, a, b + j, ldb, c + j, ldc, accumulate, last);
}

// dst (cols x ldd, ldd >= rows rounded up to 16) = src^T (src rows x cols, rows ld apart); the
// columns of dst past `rows` are zero.
void transpose_padded(Index rows, Index cols, const float* src, Index ld, float* dst, Index ldd) {
  transpose(rows, cols, src, ld, dst, ldd);
  const Index padded = (rows + kLanes - 1) / kLanes * kLanes;
  if (padded > rows)
    for (Index j = 0; j < cols; ++j) std::fill(dst + j * ldd + rows, dst + j * ldd + padded, 0.0f);
}

void avx512_gemm(ConstMatRef<float> a, Op op_a, ConstMatRef<float> b, Op op_b, MatRef<float> c,
                 bool accumulate, Buffer<float>& scratch) {
  const Index m = c.rows(), n = c.cols();
  const Index k = op_a == Op::kPlain ? a.cols() : a.rows();
  if (m == 0 || n == 0) return;
  if (k == 0) {
    if (!accumulate) c.setZero();
    return;
  }
  const float* rhs = b.data();
  Index ldb = b.outerStride();
  if (op_b == Op::kTransposed) {  // B is n x k: its transpose, k x n, into the scratch
    const Index padded = (n + kLanes - 1) / kLanes * kLanes;
    float* t = scratch.resize(k, padded).data();
    transpose_padded(n, k, b.data(), b.outerStride(), t, padded);
    rhs = t;
    ldb = padded;
  }
  const Lhs lhs{a.data(), a.outerStride()};
  if (op_a == Op::kPlain)
    product<false>(m, n, k, lhs, rhs, ldb, c.data(), c.outerStride(), accumulate);
  else
    product<true>(m, n, k, lhs, rhs, ldb, c.data(), c.outerStride(), accumulate);
}

#endif  // CORRMP_GEMM_AVX512

template <class S>
void check_gemm_shapes(ConstMatRef<S> a, Op op_a, ConstMatRef<S> b, Op op_b, MatRef<S> c) {
  const Index m = op_a == Op::kPlain ? a.rows() : a.cols();
  const Index k = op_a == Op::kPlain ? a.cols() : a.rows();
  const Index bk = op_b == Op::kPlain ? b.rows() : b.cols();
  const Index n = op_b == Op::kPlain ? b.cols() : b.rows();
  if (bk != k) throw_shape_error("gemm", "op(b)", bk, n, k, n);
  check_shape("gemm", "c", c, m, n);
}

}  // namespace

template <class S>
void gemm(ConstMatRef<S> a, Op op_a, ConstMatRef<S> b, Op op_b, MatRef<S> c, bool accumulate,
          Buffer<S>& scratch) {
  check_gemm_shapes<S>(a, op_a, b, op_b, c);
#if CORRMP_GEMM_AVX512
  if constexpr (std::is_same_v<S, float>) {
    avx512_gemm(a, op_a, b, op_b, c, accumulate, scratch);
    return;
  }
#endif
  (void)scratch;
  eigen_gemm<S>(a, op_a, b, op_b, c, accumulate);
}

bool gemm_float_split_exact() { return CORRMP_GEMM_AVX512 != 0; }

template <class S>
Buffer<S>& gemm_scratch() {
  return thread_scratch<S>(Scratch::kGemmOperand);
}

template void gemm<float>(ConstMatRef<float>, Op, ConstMatRef<float>, Op, MatRef<float>, bool,
                          Buffer<float>&);
template void gemm<double>(ConstMatRef<double>, Op, ConstMatRef<double>, Op, MatRef<double>, bool,
                           Buffer<double>&);
template Buffer<float>& gemm_scratch<float>();
template Buffer<double>& gemm_scratch<double>();

}  // namespace corrmp::nn
