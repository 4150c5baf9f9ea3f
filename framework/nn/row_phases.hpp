// Image rows split into the columns of 4-pixel-wide tiles and merged back, for the transforms of
// Winograd's F(4x4, 3x3) (nn/winograd_conv3x3.hpp; paper, Section "Learning the Context"): the
// transforms then run on one contiguous run of values per tile column, vectorised over tiles.
//
// Rows of the autoencoder's images are 16 or 32 pixels, too short for the compiler to vectorise a
// split over 4 or 8 tiles, and scalar loops cost a noticeable share of a training step
// (docs/performance.md, "Measurements behind the code"). So for float rows whose width is a
// multiple of 16, each group of 16 pixels (4 tiles) is split or merged with one 4x4 transpose of
// SSE registers (x86-64; other machines take the scalar loops everywhere); other rows take the
// scalar loops. Both give the same values.
#pragma once

#include <type_traits>

#include "nn/tensor.hpp"

#if defined(__SSE__)
#include <xmmintrin.h>
#define CORRMP_ROW_PHASES_SSE 1
#endif

namespace corrmp::nn {

namespace row_phases_detail {

#if defined(CORRMP_ROW_PHASES_SSE)
// {b[3], a[0], a[1], a[2]}: a shifted one lane up, b's last lane coming in.
inline __m128 shift_in_last(__m128 a, __m128 b) {
  const __m128 b3_a0 = _mm_shuffle_ps(b, a, _MM_SHUFFLE(0, 0, 3, 3));  // {b3, b3, a0, a0}
  return _mm_shuffle_ps(b3_a0, a, _MM_SHUFFLE(2, 1, 2, 0));
}
// {a[1], a[2], a[3], b[0]}: a shifted one lane down, b's first lane coming in.
inline __m128 shift_in_first(__m128 a, __m128 b) {
  const __m128 a3_b0 = _mm_shuffle_ps(a, b, _MM_SHUFFLE(0, 0, 3, 3));  // {a3, a3, b0, b0}
  return _mm_shuffle_ps(a, a3_b0, _MM_SHUFFLE(2, 0, 2, 1));
}
// The 16 values at in as 4 tiles' 4 pixels, by pixel: r[j] = {in[j], in[4 + j], in[8 + j],
// in[12 + j]}.
inline void load_transposed(const float* in, __m128 (&r)[4]) {
  r[0] = _mm_loadu_ps(in);
  r[1] = _mm_loadu_ps(in + 4);
  r[2] = _mm_loadu_ps(in + 8);
  r[3] = _mm_loadu_ps(in + 12);
  _MM_TRANSPOSE4_PS(r[0], r[1], r[2], r[3]);
}
// The reverse: pixel j of 4 tiles in r[j], stored as 16 values at out.
inline void store_transposed(__m128 r0, __m128 r1, __m128 r2, __m128 r3, float* out) {
  _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
  _mm_storeu_ps(out, r0);
  _mm_storeu_ps(out + 4, r1);
  _mm_storeu_ps(out + 8, r2);
  _mm_storeu_ps(out + 12, r3);
}
#endif

// Rows that the SSE path splits or merges: whole groups of 4 tiles (16 pixels).
inline bool whole_groups(Index width, Index count) { return width == 4 * count && count % 4 == 0; }

}  // namespace row_phases_detail

/// Splits a row of `width` values (zeros when row is null) by column phase:
/// phases[p phase_stride + m] = row[4 m + p] for p < 4 and m < count, 0 past the row.
template <class S>
void split_row(const S* __restrict row, Index width, Index count, S* __restrict phases,
               Index phase_stride) {
#if defined(CORRMP_ROW_PHASES_SSE)
  if constexpr (std::is_same_v<S, float>) {
    if (row != nullptr && row_phases_detail::whole_groups(width, count)) {
      for (Index m = 0; m < count; m += 4) {
        __m128 pixels[4];
        row_phases_detail::load_transposed(row + 4 * m, pixels);
        for (int p = 0; p < 4; ++p) _mm_storeu_ps(phases + p * phase_stride + m, pixels[p]);
      }
      return;
    }
  }
#endif
  for (Index m = 0; m < count; ++m)
    for (int p = 0; p < 4; ++p)
      phases[p * phase_stride + m] = row != nullptr && 4 * m + p < width ? row[4 * m + p] : S(0);
}

/// The reverse of split_row: row[w] = phases[(w mod 4) phase_stride + w div 4] for w < width.
template <class S>
void merge_row(const S* __restrict phases, Index phase_stride, Index width, Index count,
               S* __restrict row) {
#if defined(CORRMP_ROW_PHASES_SSE)
  if constexpr (std::is_same_v<S, float>) {
    if (row_phases_detail::whole_groups(width, count)) {
      for (Index m = 0; m < count; m += 4)
        row_phases_detail::store_transposed(
            _mm_loadu_ps(phases + m), _mm_loadu_ps(phases + phase_stride + m),
            _mm_loadu_ps(phases + 2 * phase_stride + m),
            _mm_loadu_ps(phases + 3 * phase_stride + m), row + 4 * m);
      return;
    }
  }
#endif
  for (Index w = 0; w < width; ++w) row[w] = phases[(w % 4) * phase_stride + w / 4];
}

/// Splits a row of `width` values, padded by one zero on the left, into the six patch columns of
/// its 4-pixel tiles: columns[q column_stride + m] = row[4 m + q - 1] for q < 6 and m < count, 0
/// outside the row.
template <class S>
void split_patch_columns(const S* __restrict row, Index width, Index count, S* __restrict columns,
                         Index column_stride) {
#if defined(CORRMP_ROW_PHASES_SSE)
  if constexpr (std::is_same_v<S, float>) {
    if (row_phases_detail::whole_groups(width, count)) {
      using row_phases_detail::shift_in_first, row_phases_detail::shift_in_last;
      const __m128 zero = _mm_setzero_ps();
      __m128 last_col4 = zero, last_col1 = zero;
      for (Index m = 0; m < count; m += 4) {
        __m128 pixels[4];  // column q + 1 of tile m is pixel 4 m + q
        row_phases_detail::load_transposed(row + 4 * m, pixels);
        for (int q = 0; q < 4; ++q) _mm_storeu_ps(columns + (q + 1) * column_stride + m, pixels[q]);
        const __m128 c1 = pixels[0], c4 = pixels[3];
        // Column 0 of tile m is column 4 of tile m - 1; column 5 is column 1 of tile m + 1.
        _mm_storeu_ps(columns + m, shift_in_last(c4, last_col4));
        if (m > 0)
          _mm_storeu_ps(columns + 5 * column_stride + m - 4, shift_in_first(last_col1, c1));
        last_col4 = c4;
        last_col1 = c1;
      }
      _mm_storeu_ps(columns + 5 * column_stride + count - 4, shift_in_first(last_col1, zero));
      return;
    }
  }
#endif
  for (Index m = 0; m < count; ++m)
    for (int q = 0; q < 6; ++q) {
      const Index w = 4 * m + q - 1;
      columns[q * column_stride + m] = w >= 0 && w < width ? row[w] : S(0);
    }
}

/// The reverse of split_patch_columns, adding the columns that overlap: row[w] for w < width is
/// column q of tile m where w = 4 m + q - 1, plus column q + 4 of tile m - 1 for q < 2.
template <class S>
void merge_patch_columns(const S* __restrict columns, Index column_stride, Index width, Index count,
                         S* __restrict row) {
#if defined(CORRMP_ROW_PHASES_SSE)
  if constexpr (std::is_same_v<S, float>) {
    if (row_phases_detail::whole_groups(width, count)) {
      using row_phases_detail::shift_in_first, row_phases_detail::shift_in_last;
      const __m128 zero = _mm_setzero_ps();
      const S* col0 = columns;
      const S* col5 = columns + 5 * column_stride;
      for (Index m = 0; m < count; m += 4) {
        // Pixel 4 m + j is column j + 1 of tile m, plus column 5 of tile m - 1 for j = 0 and
        // column 0 of tile m + 1 for j = 3.
        const __m128 before5 = m > 0 ? _mm_loadu_ps(col5 + m - 4) : zero;
        const __m128 after0 = m + 4 < count ? _mm_loadu_ps(col0 + m + 4) : zero;
        row_phases_detail::store_transposed(
            _mm_add_ps(_mm_loadu_ps(columns + column_stride + m),
                       shift_in_last(_mm_loadu_ps(col5 + m), before5)),
            _mm_loadu_ps(columns + 2 * column_stride + m),
            _mm_loadu_ps(columns + 3 * column_stride + m),
            _mm_add_ps(_mm_loadu_ps(columns + 4 * column_stride + m),
                       shift_in_first(_mm_loadu_ps(col0 + m), after0)),
            row + 4 * m);
      }
      return;
    }
  }
#endif
  for (Index w = 0; w < width; ++w) {
    const Index m = (w + 1) / 4, q = (w + 1) % 4;
    S sum = m < count ? columns[q * column_stride + m] : S(0);
    if (q < 2 && m > 0) sum += columns[(q + 4) * column_stride + m - 1];
    row[w] = sum;
  }
}

}  // namespace corrmp::nn
