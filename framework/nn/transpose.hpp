// Matrix transposes: the register-level 16 x 16 float transpose that nn/gemm.cpp's operand copy
// uses, and whole transposes between the channel-major images of the layers and the pixel-major
// planes of nn/winograd_stride2_conv3x3.hpp (which a plain loop does 5-10 times slower: one of
// its two sides is read or written a channel's size apart).
#pragma once

#include "nn/tensor.hpp"

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace corrmp::nn {

/// dst[j ldd + i] = src[i ld + j] for i < rows, j < cols; nothing else of dst is written.
/// Float runs on 16 x 16 blocks in AVX-512 registers when the build targets AVX-512.
template <class S>
void transpose(Index rows, Index cols, const S* src, Index ld, S* dst, Index ldd);
#if defined(__AVX512F__)
template <>
void transpose<float>(Index rows, Index cols, const float* src, Index ld, float* dst, Index ldd);
#endif

#if defined(__AVX512F__)
/// Transposes the 16 x 16 block r[0..15] (rows) in registers.
inline void transpose16(__m512 r[16]) {
  __m512 t[16];
  for (int i = 0; i < 8; ++i) {
    t[2 * i] = _mm512_unpacklo_ps(r[2 * i], r[2 * i + 1]);
    t[2 * i + 1] = _mm512_unpackhi_ps(r[2 * i], r[2 * i + 1]);
  }
  for (int i = 0; i < 4; ++i) {
    r[4 * i] = _mm512_shuffle_ps(t[4 * i], t[4 * i + 2], 0x44);
    r[4 * i + 1] = _mm512_shuffle_ps(t[4 * i], t[4 * i + 2], 0xEE);
    r[4 * i + 2] = _mm512_shuffle_ps(t[4 * i + 1], t[4 * i + 3], 0x44);
    r[4 * i + 3] = _mm512_shuffle_ps(t[4 * i + 1], t[4 * i + 3], 0xEE);
  }
  for (int i = 0; i < 4; ++i) {
    t[i] = _mm512_shuffle_f32x4(r[i], r[i + 4], 0x88);
    t[i + 4] = _mm512_shuffle_f32x4(r[i], r[i + 4], 0xDD);
    t[i + 8] = _mm512_shuffle_f32x4(r[i + 8], r[i + 12], 0x88);
    t[i + 12] = _mm512_shuffle_f32x4(r[i + 8], r[i + 12], 0xDD);
  }
  for (int i = 0; i < 8; ++i) {
    r[i] = _mm512_shuffle_f32x4(t[i], t[i + 8], 0x88);
    r[i + 8] = _mm512_shuffle_f32x4(t[i], t[i + 8], 0xDD);
  }
}
#endif

}  // namespace corrmp::nn
