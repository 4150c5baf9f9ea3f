// Patch unfolding / folding for the convolution layers (definitions in nn/im2col.hpp).
//
// Both work one image row at a time. Image row h of channel c feeds output row oh through
// kernel row i when oh s - p + i = h; its padded copy (p zeros on the left, zeros past the
// right edge) holds image column w at padded column w' = w + p, and output column ow of kernel
// column j reads padded column ow s + j. Split by column phase, w' going to
// phase (w' mod s), index (w' div s), the out_width columns that kernel column j reads are one
// contiguous run (phase j mod s, from index j div s): each row (c, i, j) segment of cols is a
// plain copy of (im2col) or sum into (col2im) such a run, with no bounds to check, so the loops
// vectorise. The common strides 1 and 2 are compiled with the stride as a constant; the
// autoencoder's kernel 3 / stride 2 / padding 1 has its own code (nn/im2col_k3s2p1.hpp).
#include "nn/im2col.hpp"

#include <algorithm>
#include <vector>

#include "nn/im2col_k3s2p1.hpp"

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
