// im2col and col2im for kernel 3, stride 2, padding 1 (nn/im2col_k3s2p1.hpp).
//
// Output (oh, ow) reads image rows 2 oh - 1 + i and columns 2 ow - 1 + j: kernel column 1 reads
// the even columns, 2 the odd ones and 0 the odd ones shifted by one. Both work one image row at
// a time; col2im sums each image pixel's contributions before adding them. Float rows on x86-64
// with AVX-512 (the build's -march=native) take 16 outputs per step: even and odd columns split
// and interleaved with permutes, every value computed by the same operations in the same order
// as the scalar loops, so both give the same bits (GCC vectorises only some of the scalar loops'
// strided copies).
#include "nn/im2col_k3s2p1.hpp"

#include <algorithm>

#if defined(__AVX512F__)
#include <immintrin.h>
#define CORRMP_IM2COL_AVX512 1
#else
#define CORRMP_IM2COL_AVX512 0
#endif

namespace corrmp::nn {
namespace {

// One image row of the k3s2p1 unfolding: j0, j1 and j2 get the out_width values that kernel
// columns 0, 1 and 2 read from the row `src` (2 out_width values).
template <class S>
void unfold_row_k3s2p1(const S* __restrict src, Index wo, S* __restrict j0, S* __restrict j1,
                       S* __restrict j2) {
  j0[0] = S(0);
  for (Index ow = 1; ow < wo; ++ow) j0[ow] = src[2 * ow - 1];
  for (Index ow = 0; ow < wo; ++ow) j1[ow] = src[2 * ow];
  for (Index ow = 0; ow < wo; ++ow) j2[ow] = src[2 * ow + 1];
}

// Adds the folded taps of one image row: row[2 ow] += a1[ow] (+ b1[ow]) and row[2 ow + 1] +=
// a2[ow] + a0[ow + 1] (+ (b2[ow] + b0[ow + 1])), a0[ow + 1] and b0[ow + 1] only while
// ow + 1 < wo; b = nullptr when only one kernel row feeds the image row.
template <class S>
void fold_row_k3s2p1(const S* const* a, const S* const* b, Index wo, S* __restrict row) {
  const S *a0 = a[0], *a1 = a[1], *a2 = a[2];
  if (b == nullptr) {
    for (Index ow = 0; ow + 1 < wo; ++ow) {
      row[2 * ow] += a1[ow];
      row[2 * ow + 1] += a2[ow] + a0[ow + 1];
    }
    row[2 * wo - 2] += a1[wo - 1];
    row[2 * wo - 1] += a2[wo - 1];
    return;
  }
  const S *b0 = b[0], *b1 = b[1], *b2 = b[2];
  for (Index ow = 0; ow + 1 < wo; ++ow) {
    row[2 * ow] += a1[ow] + b1[ow];
    row[2 * ow + 1] += (a2[ow] + a0[ow + 1]) + (b2[ow] + b0[ow + 1]);
  }
  row[2 * wo - 2] += a1[wo - 1] + b1[wo - 1];
  row[2 * wo - 1] += a2[wo - 1] + b2[wo - 1];
}

#if CORRMP_IM2COL_AVX512
// Lanes 0 .. n - 1 of a 16-float vector (none for n <= 0, all for n >= 16).
__mmask16 first_lanes(Index n) {
  if (n <= 0) return 0;
  return n >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << n) - 1);
}

// The two row functions for float, 16 outputs per step; every value is computed by the same
// operations in the same order as above, so both give the same bits.

template <>
void unfold_row_k3s2p1<float>(const float* __restrict src, Index wo, float* __restrict j0,
                              float* __restrict j1, float* __restrict j2) {
  const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  const __m512i odd = _mm512_setr_epi32(1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31);
  __m512i previous_odd = _mm512_setzero_si512();  // src[2 ow - 1] of the lanes before
  for (Index ow = 0; ow < wo; ow += 16) {
    const Index n = std::min<Index>(16, wo - ow);
    const __m512 lo = _mm512_maskz_loadu_ps(first_lanes(2 * n), src + 2 * ow);
    const __m512 hi = _mm512_maskz_loadu_ps(first_lanes(2 * n - 16), src + 2 * ow + 16);
    const __m512i odd_values = _mm512_castps_si512(_mm512_permutex2var_ps(lo, odd, hi));
    const __mmask16 out = first_lanes(n);
    _mm512_mask_storeu_ps(j0 + ow, out,
                          _mm512_castsi512_ps(_mm512_alignr_epi32(odd_values, previous_odd, 15)));
    _mm512_mask_storeu_ps(j1 + ow, out, _mm512_permutex2var_ps(lo, even, hi));
    _mm512_mask_storeu_ps(j2 + ow, out, _mm512_castsi512_ps(odd_values));
    previous_odd = odd_values;
  }
}

template <>
void fold_row_k3s2p1<float>(const float* const* a, const float* const* b, Index wo,
                            float* __restrict row) {
  const __m512i first_half =
      _mm512_setr_epi32(0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23);
  const __m512i second_half =
      _mm512_setr_epi32(8, 24, 9, 25, 10, 26, 11, 27, 12, 28, 13, 29, 14, 30, 15, 31);
  for (Index ow = 0; ow < wo; ow += 16) {
    const Index n = std::min<Index>(16, wo - ow);
    const __mmask16 lanes = first_lanes(n), next = first_lanes(wo - ow - 1);
    // a2[ow] + a0[ow + 1] where ow + 1 < wo, a2[ow] alone at the last output.
    const auto odd_sum = [&](const float* const* k) {
      const __m512 k2 = _mm512_maskz_loadu_ps(lanes, k[2] + ow);
      return _mm512_mask_add_ps(k2, next, k2, _mm512_maskz_loadu_ps(next, k[0] + ow + 1));
    };
    __m512 even_sum = _mm512_maskz_loadu_ps(lanes, a[1] + ow), odd = odd_sum(a);
    if (b != nullptr) {
      even_sum = _mm512_add_ps(even_sum, _mm512_maskz_loadu_ps(lanes, b[1] + ow));
      odd = _mm512_add_ps(odd, odd_sum(b));
    }
    const __mmask16 lo = first_lanes(2 * n), hi = first_lanes(2 * n - 16);
    float* out = row + 2 * ow;
    _mm512_mask_storeu_ps(out, lo,
                          _mm512_add_ps(_mm512_maskz_loadu_ps(lo, out),
                                        _mm512_permutex2var_ps(even_sum, first_half, odd)));
    _mm512_mask_storeu_ps(out + 16, hi,
                          _mm512_add_ps(_mm512_maskz_loadu_ps(hi, out + 16),
                                        _mm512_permutex2var_ps(even_sum, second_half, odd)));
  }
}
#endif

}  // namespace

bool is_k3s2p1(const PatchGeometry& g) {
  return g.kernel == 3 && g.stride == 2 && g.padding == 1 && g.image.height == 2 * g.out_height &&
         g.image.width == 2 * g.out_width;
}

template <class S>
void unfold_k3s2p1(const S* images, Index image_stride, const PatchGeometry& g,
                   const PositionChunk& chunk, S* cols) {
  const Index H = g.image.height, W = g.image.width, Wo = g.out_width;
  const Index P = chunk.positions(g), row_stride = chunk.columns(g);
  for (Index c = 0; c < g.image.channels; ++c)
    for (Index i = 0; i < 3; ++i) {
      S* rows = cols + (c * 3 + i) * 3 * row_stride;  // row (c, i, 0)
      for (Index n = 0; n < chunk.images; ++n) {
        const S* channel = images + (chunk.image_begin + n) * image_stride + c * H * W;
        for (Index oh = chunk.row_begin; oh < chunk.row_end; ++oh) {
          S* j0 = rows + n * P + (oh - chunk.row_begin) * Wo;
          S* j1 = j0 + row_stride;
          S* j2 = j1 + row_stride;
          const Index h = 2 * oh - 1 + i;
          if (h < 0 || h >= H) {
            std::fill(j0, j0 + Wo, S(0));
            std::fill(j1, j1 + Wo, S(0));
            std::fill(j2, j2 + Wo, S(0));
            continue;
          }
          unfold_row_k3s2p1(channel + h * W, Wo, j0, j1, j2);
        }
      }
    }
}

template <class S>
void fold_k3s2p1(const S* cols, const PatchGeometry& g, const PositionChunk& chunk, S* images,
                 Index image_stride, const S* channel_bias) {
  const Index H = g.image.height, W = g.image.width, Wo = g.out_width;
  const Index P = chunk.positions(g), row_stride = chunk.columns(g);
  if (chunk.row_begin == 0)
    for (Index n = 0; n < chunk.images; ++n)
      for (Index c = 0; c < g.image.channels; ++c) {
        S* channel = images + (chunk.image_begin + n) * image_stride + c * H * W;
        std::fill(channel, channel + H * W, channel_bias ? channel_bias[c] : S(0));
      }
  // Image rows the chunk's output rows feed: 2 oh - 1 + i.
  const Index first = std::max<Index>(0, 2 * chunk.row_begin - 1);
  const Index last = std::min<Index>(H, 2 * chunk.row_end);  // exclusive
  for (Index c = 0; c < g.image.channels; ++c)
    for (Index n = 0; n < chunk.images; ++n) {
      S* channel = images + (chunk.image_begin + n) * image_stride + c * H * W;
      const S* image_cols = cols + c * 9 * row_stride + n * P - chunk.row_begin * Wo;
      for (Index h = first; h < last; ++h) {
        // Row h = 2 oh - 1 + i: i = 1 with oh = h / 2 for even h; i = 0 with oh = (h + 1) / 2
        // and i = 2 with oh = (h - 1) / 2 for odd h.
        const S* taps[2][3];  // up to two kernel rows, their columns j = 0, 1, 2
        int count = 0;
        const auto add_tap = [&](Index i, Index oh) {
          if (oh < chunk.row_begin || oh >= chunk.row_end) return;
          for (Index j = 0; j < 3; ++j)
            taps[count][j] = image_cols + (i * 3 + j) * row_stride + oh * Wo;
          ++count;
        };
        if (h % 2 == 0) {
          add_tap(1, h / 2);
        } else {
          add_tap(0, (h + 1) / 2);
          add_tap(2, (h - 1) / 2);
        }
        // Column 2 ow gets j = 1 at ow; column 2 ow + 1 gets j = 2 at ow and j = 0 at ow + 1.
        if (count > 0)
          fold_row_k3s2p1<S>(taps[0], count == 2 ? taps[1] : nullptr, Wo, channel + h * W);
      }
    }
}

template void unfold_k3s2p1<float>(const float*, Index, const PatchGeometry&, const PositionChunk&,
                                   float*);
template void unfold_k3s2p1<double>(const double*, Index, const PatchGeometry&,
                                    const PositionChunk&, double*);
template void fold_k3s2p1<float>(const float*, const PatchGeometry&, const PositionChunk&, float*,
                                 Index, const float*);
template void fold_k3s2p1<double>(const double*, const PatchGeometry&, const PositionChunk&,
                                  double*, Index, const double*);

}  // namespace corrmp::nn
