// Tests of nn/gemm.hpp: every operand layout against a double-precision loop, on sizes around the
// kernel's 8 x 32 blocks and on views into larger matrices; the float kernel's summation order;
// shape errors; the scratch buffer's reuse.
#include "nn/gemm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace corrmp::nn {
namespace {

template <class S>
Mat<S> random_matrix(Index rows, Index cols, unsigned seed) {
  Mat<S> m(rows, cols);
  unsigned state = seed * 2654435761u + 1u;
  for (Index i = 0; i < m.size(); ++i) {
    state = state * 1664525u + 1013904223u;
    m.data()[i] = static_cast<S>((state >> 8) % 2001u) / S(1000) - S(1);  // in [-1, 1]
  }
  return m;
}

template <class S>
Mat<S> apply(const Mat<S>& x, Op op) {
  return op == Op::kPlain ? x : Mat<S>(x.transpose());
}

struct Shape {
  Index m, n, k;
};

// Around the kernel's block sizes (8 rows, 2 x 16 columns), with the autoencoder's smallest K.
const Shape kShapes[] = {{1, 1, 1},   {7, 15, 3},   {8, 16, 5},    {9, 17, 27},
                         {16, 32, 1}, {17, 33, 64}, {27, 27, 100}, {64, 48, 9},
                         {3, 100, 2}, {40, 5, 31},  {13, 64, 0}};

template <class S>
void check_all_layouts(S tolerance) {
  for (const Shape& s : kShapes)
    for (Op op_a : {Op::kPlain, Op::kTransposed})
      for (Op op_b : {Op::kPlain, Op::kTransposed})
        for (bool accumulate : {false, true}) {
          const std::string what = "m" + std::to_string(s.m) + " n" + std::to_string(s.n) + " k" +
                                   std::to_string(s.k) + (op_a == Op::kPlain ? " A" : " A^T") +
                                   (op_b == Op::kPlain ? " B" : " B^T") +
                                   (accumulate ? " +=" : " =");
          const Mat<S> a = apply(random_matrix<S>(s.m, s.k, 1), op_a);
          const Mat<S> b = apply(random_matrix<S>(s.k, s.n, 2), op_b);
          const Mat<S> c0 = random_matrix<S>(s.m, s.n, 3);
          Mat<S> c = c0;
          Buffer<S> scratch;
          gemm<S>(a, op_a, b, op_b, c, accumulate, scratch);
          const Mat<double> expected =
              (accumulate ? Mat<double>(c0.template cast<double>()) : Mat<double>::Zero(s.m, s.n)) +
              apply(a, op_a).template cast<double>() * apply(b, op_b).template cast<double>();
          ASSERT_EQ(c.rows(), s.m);
          for (Index i = 0; i < s.m; ++i)
            for (Index j = 0; j < s.n; ++j)
              ASSERT_NEAR(static_cast<double>(c(i, j)), expected(i, j),
                          tolerance * static_cast<double>(s.k + 1))
                  << what << " at (" << i << ", " << j << ")";
        }
}

TEST(Gemm, FloatMatchesTheProductForEveryLayout) { check_all_layouts<float>(1e-6f); }

TEST(Gemm, DoubleMatchesTheProductForEveryLayout) { check_all_layouts<double>(1e-14); }

// A block of a larger matrix for every operand: rows lie further apart than their length, and
// the entries around the output block stay as they were.
TEST(Gemm, WorksOnViewsIntoLargerMatrices) {
  const Index m = 11, n = 37, k = 19;
  const Mat<float> big_a = random_matrix<float>(k + 5, m + 9, 4);  // holds A^T
  const Mat<float> big_b = random_matrix<float>(n + 3, k + 7, 5);  // holds B^T
  Mat<float> big_c = random_matrix<float>(m + 4, n + 6, 6);
  const Mat<float> before = big_c;
  Buffer<float> scratch;
  gemm<float>(big_a.block(2, 3, k, m), Op::kTransposed, big_b.block(1, 4, n, k), Op::kTransposed,
              big_c.block(1, 2, m, n), /*accumulate=*/true, scratch);
  const Mat<double> expected = before.block(1, 2, m, n).cast<double>() +
                               big_a.block(2, 3, k, m).transpose().cast<double>() *
                                   big_b.block(1, 4, n, k).transpose().cast<double>();
  for (Index i = 0; i < big_c.rows(); ++i)
    for (Index j = 0; j < big_c.cols(); ++j) {
      const bool inside = i >= 1 && i < 1 + m && j >= 2 && j < 2 + n;
      if (inside)
        EXPECT_NEAR(big_c(i, j), expected(i - 1, j - 2), 1e-5) << i << ", " << j;
      else
        EXPECT_EQ(big_c(i, j), before(i, j)) << i << ", " << j;
    }
}

#if defined(__AVX512F__)
// The float kernel sums each entry over p = 0, 1, ..., K - 1 in order with fused multiply-adds,
// so its result is fixed by the operands alone (whatever block or strip the entry falls in).
TEST(Gemm, FloatEntriesAreOrderedFusedSums) {
  const Index m = 19, n = 45, k = 70;
  const Mat<float> a = random_matrix<float>(m, k, 7);
  const Mat<float> b = random_matrix<float>(k, n, 8);
  Mat<float> c(m, n);
  Buffer<float> scratch;
  gemm<float>(a, Op::kPlain, b, Op::kPlain, c, /*accumulate=*/false, scratch);
  for (Index i = 0; i < m; ++i)
    for (Index j = 0; j < n; ++j) {
      float sum = 0.0f;
      for (Index p = 0; p < k; ++p) sum = std::fma(a(i, p), b(p, j), sum);
      ASSERT_EQ(c(i, j), sum) << i << ", " << j;
    }
}
#endif

TEST(Gemm, RejectsMismatchedShapes) {
  const Mat<float> a(3, 4), b(5, 6);
  Mat<float> c(3, 6);
  Buffer<float> scratch;
  EXPECT_THROW(gemm<float>(a, Op::kPlain, b, Op::kPlain, c, false, scratch), std::invalid_argument);
  const Mat<float> b_ok(4, 6);
  Mat<float> c_wrong(3, 5);
  EXPECT_THROW(gemm<float>(a, Op::kPlain, b_ok, Op::kPlain, c_wrong, false, scratch),
               std::invalid_argument);
  EXPECT_NO_THROW(gemm<float>(a, Op::kPlain, b_ok, Op::kPlain, c, false, scratch));
}

TEST(Gemm, ScratchIsReusedForTheSameShape) {
  const Mat<float> a = random_matrix<float>(8, 40, 9), b = random_matrix<float>(33, 40, 10);
  Mat<float> c(8, 33);
  Buffer<float> scratch;
  gemm<float>(a, Op::kPlain, b, Op::kTransposed, c, false, scratch);
  const Index capacity = scratch.capacity();
  gemm<float>(a, Op::kPlain, b, Op::kTransposed, c, true, scratch);
  EXPECT_EQ(scratch.capacity(), capacity);
}

}  // namespace
}  // namespace corrmp::nn
