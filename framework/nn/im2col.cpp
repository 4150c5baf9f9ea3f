// Patch unfolding / folding for the convolution layers (definitions in nn/im2col.hpp).
//
// Both work one image row at a time. Image row h of channel c feeds output row oh through
// kernel row i when oh s - p + i = h; its padded copy (p zeros on the left, zeros past the
// right edge) holds image column w at padded column w' = w + p, and output column ow of kernel
// column j reads padded column ow s + j. Split by column phase, w' going to
// phase (w' mod s), index (w' div s), the out_width columns that kernel column j reads are one
// contiguous run (phase j mod s, from index j div s): each row (c, i, j) segment of cols is a
// plain copy of (im2col) or sum into (col2im) such a run, with no bounds to check, so the loops
// vectorise. The common strides 1 and 2 are compiled with the stride as a constant.
#include "nn/im2col.hpp"

#include <algorithm>
#include <vector>

#if defined(__AVX512F__)
#include <immintrin.h>
#define CORRMP_IM2COL_AVX512 1
#else
#define CORRMP_IM2COL_AVX512 0
#endif

namespace corrmp::nn {
namespace {

// One image row, zero-padded and split by column phase (see the file comment).
template <class S>
class PaddedRow {
 public:
  explicit PaddedRow(const PatchGeometry& g)
      : stride_(g.stride),
        padding_(g.padding),
        width_(g.image.width),
        length_(g.out_width + (g.kernel - 1) / g.stride) {
    if (stride_ * length_ > kStackValues) {
      heap_.resize(static_cast<size_t>(stride_ * length_));
      values_ = heap_.data();
    }
    if (g.kernel > kStackKernel) {
      heap_offsets_.resize(static_cast<size_t>(g.kernel));
      offsets_ = heap_offsets_.data();
    }
    for (Index j = 0; j < g.kernel; ++j) offsets_[j] = (j % stride_) * length_ + j / stride_;
  }

  // Where kernel column j reads: output column ow of row (c, i, j) is at(j)[ow].
  S* at(Index j) { return values_ + offsets_[j]; }

  // The padded columns w' = idx s + phase that hold image column w = w' - p, as idx in
  // [begin, end).
  Index begin(Index phase) const {
    return std::max<Index>(0, (padding_ - phase + stride_ - 1) / stride_);
  }
  Index end(Index phase) const {
    const Index last = width_ - 1 + padding_ - phase;  // idx s <= last
    return last < 0 ? 0 : std::min(length_, last / stride_ + 1);
  }

  // Fills the row from an image row (zeros in the padding).
  template <Index kStride>
  void load(const S* __restrict row) {
    const Index s = kStride > 0 ? kStride : stride_;
    for (Index phase = 0; phase < s; ++phase) {
      S* __restrict out = values_ + phase * length_;
      const Index b = std::min(begin(phase), length_), e = std::max(end(phase), b);
      const S* in = row + phase - padding_;  // out[idx] = in[idx s]
      std::fill(out, out + b, S(0));
      for (Index idx = b; idx < e; ++idx) out[idx] = in[idx * s];
      std::fill(out + e, out + length_, S(0));
    }
  }

  void clear() { std::fill(values_, values_ + stride_ * length_, S(0)); }

  // Adds the row's image columns into an image row.
  template <Index kStride>
  void add_to(S* __restrict row) const {
    const Index s = kStride > 0 ? kStride : stride_;
    for (Index phase = 0; phase < s; ++phase) {
      const S* __restrict in = values_ + phase * length_;
      S* out = row + phase - padding_;  // out[idx s] += in[idx]
      const Index b = std::min(begin(phase), length_), e = std::max(end(phase), b);
      for (Index idx = b; idx < e; ++idx) out[idx * s] += in[idx];
    }
  }

 private:
  static constexpr Index kStackValues = 512;
  static constexpr Index kStackKernel = 16;
  Index stride_, padding_, width_, length_;
  S stack_[kStackValues];
  Index stack_offsets_[kStackKernel];
  std::vector<S> heap_;              // only for rows wider than kStackValues
  std::vector<Index> heap_offsets_;  // only for kernels wider than kStackKernel
  S* values_ = stack_;
  Index* offsets_ = stack_offsets_;  // at(j) - values_
};

// The image rows h that output rows [row_begin, row_end) read: oh s - p + i for i in [0, k).
struct RowRange {
  Index begin;
  Index end;
};
RowRange source_rows(const PatchGeometry& g, const PositionChunk& chunk) {
  const Index first = chunk.row_begin * g.stride - g.padding;
  const Index last = (chunk.row_end - 1) * g.stride - g.padding + g.kernel;  // exclusive
  return {std::max<Index>(0, first), std::min(g.image.height, last)};
}

// The output row of the chunk that image row h feeds through kernel row i, or -1.
template <Index kStride>
Index output_row(const PatchGeometry& g, const PositionChunk& chunk, Index h, Index i) {
  const Index s = kStride > 0 ? kStride : g.stride;
  const Index t = h + g.padding - i;  // = oh s
  if (t < 0 || t % s != 0) return -1;
  const Index oh = t / s;
  return oh >= chunk.row_begin && oh < chunk.row_end ? oh : -1;
}

// kStride is the stride when known at compile time, 0 otherwise.
template <class S, Index kStride>
void unfold(const S* images, Index image_stride, const PatchGeometry& g, const PositionChunk& chunk,
            S* cols) {
  const Index H = g.image.height, W = g.image.width, k = g.kernel, s = g.stride;
  const Index Wo = g.out_width, P = chunk.positions(g);
  const Index row_stride = chunk.columns(g);  // distance between rows of cols
  const RowRange rows = source_rows(g, chunk);
  PaddedRow<S> padded(g);
  for (Index c = 0; c < g.image.channels; ++c) {
    S* channel_cols = cols + c * k * k * row_stride;  // row (c, 0, 0)
    for (Index n = 0; n < chunk.images; ++n) {
      S* image_cols = channel_cols + n * P - chunk.row_begin * Wo;  // + oh Wo: output row oh
      // Output rows whose kernel row i falls in the vertical padding read zeros.
      for (Index i = 0; i < k; ++i)
        for (Index oh = chunk.row_begin; oh < chunk.row_end; ++oh) {
          const Index h = oh * s - g.padding + i;
          if (h >= 0 && h < H) continue;
          for (Index j = 0; j < k; ++j) {
            S* dst = image_cols + (i * k + j) * row_stride + oh * Wo;
            std::fill(dst, dst + Wo, S(0));
          }
        }
      const S* channel = images + (chunk.image_begin + n) * image_stride + c * H * W;
      for (Index h = rows.begin; h < rows.end; ++h) {
        padded.template load<kStride>(channel + h * W);
        for (Index i = 0; i < k; ++i) {
          const Index oh = output_row<kStride>(g, chunk, h, i);
          if (oh < 0) continue;
          for (Index j = 0; j < k; ++j) {
            S* __restrict dst = image_cols + (i * k + j) * row_stride + oh * Wo;
            const S* __restrict src = padded.at(j);
            for (Index ow = 0; ow < Wo; ++ow) dst[ow] = src[ow];
          }
        }
      }
    }
  }
}

template <class S, Index kStride>
void fold(const S* cols, const PatchGeometry& g, const PositionChunk& chunk, S* images,
          Index image_stride, const S* channel_bias) {
  const Index H = g.image.height, W = g.image.width, k = g.kernel;
  const Index Wo = g.out_width, P = chunk.positions(g);
  const Index row_stride = chunk.columns(g);
  const RowRange rows = source_rows(g, chunk);
  PaddedRow<S> padded(g);
  if (chunk.row_begin == 0)
    for (Index n = 0; n < chunk.images; ++n)
      for (Index c = 0; c < g.image.channels; ++c) {
        S* channel = images + (chunk.image_begin + n) * image_stride + c * H * W;
        std::fill(channel, channel + H * W, channel_bias ? channel_bias[c] : S(0));
      }
  for (Index c = 0; c < g.image.channels; ++c) {
    const S* channel_cols = cols + c * k * k * row_stride;
    for (Index n = 0; n < chunk.images; ++n) {
      const S* image_cols = channel_cols + n * P - chunk.row_begin * Wo;
      S* channel = images + (chunk.image_begin + n) * image_stride + c * H * W;
      for (Index h = rows.begin; h < rows.end; ++h) {
        padded.clear();
        for (Index i = 0; i < k; ++i) {
          const Index oh = output_row<kStride>(g, chunk, h, i);
          if (oh < 0) continue;
          for (Index j = 0; j < k; ++j) {
            S* __restrict dst = padded.at(j);
            const S* __restrict src = image_cols + (i * k + j) * row_stride + oh * Wo;
            for (Index ow = 0; ow < Wo; ++ow) dst[ow] += src[ow];
          }
        }
        padded.template add_to<kStride>(channel + h * W);
      }
    }
  }
}

// The autoencoder's downsampling geometry, kernel 3, stride 2, padding 1 on an image of twice
// the output size, written out: output (oh, ow) reads image rows 2 oh - 1 + i and columns
// 2 ow - 1 + j, so kernel column 1 reads the even columns, 2 the odd ones and 0 the odd ones
// shifted by one. Both loops read only memory written before the call (no freshly stored
// values are read back), and col2im sums each image pixel's contributions before adding them.
bool is_k3s2p1(const PatchGeometry& g) {
  return g.kernel == 3 && g.stride == 2 && g.padding == 1 && g.image.height == 2 * g.out_height &&
         g.image.width == 2 * g.out_width;
}

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
// The same for float rows, 16 outputs per step; every value is computed by the same operations
// in the same order as above, so both give the same bits.
__mmask16 first_lanes(Index n) { return n >= 16 ? __mmask16(0xFFFF) : __mmask16((1u << n) - 1); }

template <>
void unfold_row_k3s2p1<float>(const float* __restrict src, Index wo, float* __restrict j0,
                              float* __restrict j1, float* __restrict j2) {
  const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  const __m512i odd = _mm512_setr_epi32(1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31);
  __m512i previous_odd = _mm512_setzero_si512();  // src[2 ow - 1] of the lanes before
  for (Index ow = 0; ow < wo; ow += 16) {
    const Index n = std::min<Index>(16, wo - ow);
    const __m512 lo = _mm512_maskz_loadu_ps(first_lanes(2 * n), src + 2 * ow);
    const __m512 hi =
        _mm512_maskz_loadu_ps(first_lanes(std::max<Index>(0, 2 * n - 16)), src + 2 * ow + 16);
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
    const __mmask16 lo = first_lanes(2 * n), hi = first_lanes(std::max<Index>(0, 2 * n - 16));
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

}  // namespace

template <class S>
void im2col_chunk(const S* images, Index image_stride, const PatchGeometry& g,
                  const PositionChunk& chunk, S* cols) {
  if (is_k3s2p1(g))
    unfold_k3s2p1(images, image_stride, g, chunk, cols);
  else if (g.stride == 1)
    unfold<S, 1>(images, image_stride, g, chunk, cols);
  else if (g.stride == 2)
    unfold<S, 2>(images, image_stride, g, chunk, cols);
  else
    unfold<S, 0>(images, image_stride, g, chunk, cols);
}

template <class S>
void col2im_chunk(const S* cols, const PatchGeometry& g, const PositionChunk& chunk, S* images,
                  Index image_stride, const S* channel_bias) {
  if (is_k3s2p1(g))
    fold_k3s2p1(cols, g, chunk, images, image_stride, channel_bias);
  else if (g.stride == 1)
    fold<S, 1>(cols, g, chunk, images, image_stride, channel_bias);
  else if (g.stride == 2)
    fold<S, 2>(cols, g, chunk, images, image_stride, channel_bias);
  else
    fold<S, 0>(cols, g, chunk, images, image_stride, channel_bias);
}

template <class S>
void im2col(const S* image, const PatchGeometry& g, S* cols) {
  im2col_chunk(image, g.image.size(), g, PositionChunk{0, 1, 0, g.out_height}, cols);
}

template <class S>
void col2im(const S* cols, const PatchGeometry& g, S* image) {
  col2im_chunk(cols, g, PositionChunk{0, 1, 0, g.out_height}, image, g.image.size());
}

template void im2col<float>(const float*, const PatchGeometry&, float*);
template void im2col<double>(const double*, const PatchGeometry&, double*);
template void col2im<float>(const float*, const PatchGeometry&, float*);
template void col2im<double>(const double*, const PatchGeometry&, double*);
template void im2col_chunk<float>(const float*, Index, const PatchGeometry&, const PositionChunk&,
                                  float*);
template void im2col_chunk<double>(const double*, Index, const PatchGeometry&, const PositionChunk&,
                                   double*);
template void col2im_chunk<float>(const float*, const PatchGeometry&, const PositionChunk&, float*,
                                  Index, const float*);
template void col2im_chunk<double>(const double*, const PatchGeometry&, const PositionChunk&,
                                   double*, Index, const double*);

}  // namespace corrmp::nn
