// Matrix transposes (nn/transpose.hpp).
#include "nn/transpose.hpp"

#include <algorithm>

namespace corrmp::nn {

template <class S>
void transpose(Index rows, Index cols, const S* src, Index ld, S* dst, Index ldd) {
  constexpr Index kBlock = 16;  // blocks that stay in L1 on both sides
  for (Index c0 = 0; c0 < cols; c0 += kBlock)
    for (Index r0 = 0; r0 < rows; r0 += kBlock) {
      const Index c1 = std::min(cols, c0 + kBlock), r1 = std::min(rows, r0 + kBlock);
      for (Index j = c0; j < c1; ++j)
        for (Index i = r0; i < r1; ++i) dst[j * ldd + i] = src[i * ld + j];
    }
}

#if defined(__AVX512F__)
template <>
void transpose<float>(Index rows, Index cols, const float* src, Index ld, float* dst, Index ldd) {
  constexpr Index kLanes = 16;
  for (Index c0 = 0; c0 < cols; c0 += kLanes) {
    const Index width = std::min<Index>(kLanes, cols - c0);
    const __mmask16 columns = width == kLanes ? __mmask16(0xFFFF) : __mmask16((1u << width) - 1);
    for (Index r0 = 0; r0 < rows; r0 += kLanes) {
      const Index height = std::min<Index>(kLanes, rows - r0);
      const __mmask16 lanes = height == kLanes ? __mmask16(0xFFFF) : __mmask16((1u << height) - 1);
      __m512 block[kLanes];
      for (Index i = 0; i < kLanes; ++i)
        block[i] = i < height ? _mm512_maskz_loadu_ps(columns, src + (r0 + i) * ld + c0)
                              : _mm512_setzero_ps();
      transpose16(block);
      for (Index i = 0; i < width; ++i)
        _mm512_mask_storeu_ps(dst + (c0 + i) * ldd + r0, lanes, block[i]);
    }
  }
}
#endif

template void transpose<float>(Index, Index, const float*, Index, float*, Index);
template void transpose<double>(Index, Index, const double*, Index, double*, Index);

}  // namespace corrmp::nn
