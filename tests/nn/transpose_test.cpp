// Tests of nn/transpose.hpp: every entry moved, nothing else of the destination written, on sizes
// around the 16 x 16 blocks of the float path, in float and double.
#include "nn/transpose.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace corrmp::nn {
namespace {

template <class S>
void expect_transposed(Index rows, Index cols) {
  const Index ld = cols + 3, ldd = rows + 5;  // strided on both sides
  std::vector<S> src(static_cast<size_t>(rows * ld));
  for (size_t i = 0; i < src.size(); ++i) src[i] = static_cast<S>(i) + S(0.5);
  const S untouched(-7);
  std::vector<S> dst(static_cast<size_t>(cols * ldd + 16), untouched);
  transpose(rows, cols, src.data(), ld, dst.data(), ldd);
  for (Index j = 0; j < cols; ++j)
    for (Index i = 0; i < ldd; ++i) {
      const S got = dst[static_cast<size_t>(j * ldd + i)];
      if (i < rows)
        ASSERT_EQ(got, src[static_cast<size_t>(i * ld + j)]) << rows << "x" << cols;
      else
        ASSERT_EQ(got, untouched) << "wrote past the rows at " << j << ", " << i;
    }
  for (size_t k = static_cast<size_t>(cols * ldd); k < dst.size(); ++k)
    ASSERT_EQ(dst[k], untouched);
}

TEST(Transpose, MovesEveryEntryAndWritesNothingElse) {
  for (const Index rows : {1, 3, 15, 16, 17, 32, 40})
    for (const Index cols : {1, 8, 16, 19, 33}) {
      expect_transposed<float>(rows, cols);
      expect_transposed<double>(rows, cols);
    }
}

}  // namespace
}  // namespace corrmp::nn
