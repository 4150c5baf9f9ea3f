// Patch unfolding / folding for the convolution layers (definitions in nn/im2col.hpp).
//
// Both loops run over (channel, kernel row i, kernel column j, output row oh). For a fixed
// kernel column j, the output columns ow whose source column ow s - p + j lies inside the image
// form one contiguous range [ow_begin, ow_end); everything outside it is padding.
#include "nn/im2col.hpp"

#include <algorithm>

namespace corrmp::nn {
namespace {

struct ColumnRange {
  Index begin;
  Index end;
};

// Output columns ow with 0 <= ow * stride - padding + j < width.
ColumnRange valid_columns(const PatchGeometry& g, Index j) {
  const Index s = g.stride;
  const Index lo_num = g.padding - j;  // need ow * s >= padding - j
  Index begin = lo_num <= 0 ? 0 : (lo_num + s - 1) / s;
  const Index hi_num = g.image.width - 1 + g.padding - j;  // need ow * s <= width - 1 + p - j
  Index end = hi_num < 0 ? 0 : std::min(g.out_width, hi_num / s + 1);
  begin = std::min(begin, g.out_width);
  end = std::max(end, begin);
  return {begin, end};
}

}  // namespace

template <class S>
void im2col(const S* image, const PatchGeometry& g, S* cols) {
  const Index H = g.image.height, W = g.image.width, k = g.kernel, s = g.stride;
  const Index Ho = g.out_height, Wo = g.out_width;
  S* dst_row = cols;
  for (Index c = 0; c < g.image.channels; ++c) {
    const S* channel = image + c * H * W;
    for (Index i = 0; i < k; ++i) {
      for (Index j = 0; j < k; ++j, dst_row += Ho * Wo) {
        const ColumnRange range = valid_columns(g, j);
        for (Index oh = 0; oh < Ho; ++oh) {
          S* dst = dst_row + oh * Wo;
          const Index h = oh * s - g.padding + i;
          if (h < 0 || h >= H) {
            std::fill(dst, dst + Wo, S(0));
            continue;
          }
          const S* src = channel + h * W;
          const Index offset = j - g.padding;  // column ow reads src[ow * s + offset]
          std::fill(dst, dst + range.begin, S(0));
          if (s == 1 && range.end > range.begin) {
            std::copy(src + range.begin + offset, src + range.end + offset, dst + range.begin);
          } else {
            for (Index ow = range.begin; ow < range.end; ++ow) dst[ow] = src[ow * s + offset];
          }
          std::fill(dst + range.end, dst + Wo, S(0));
        }
      }
    }
  }
}

template <class S>
void col2im(const S* cols, const PatchGeometry& g, S* image) {
  const Index H = g.image.height, W = g.image.width, k = g.kernel, s = g.stride;
  const Index Ho = g.out_height, Wo = g.out_width;
  std::fill(image, image + g.image.size(), S(0));
  const S* src_row = cols;
  for (Index c = 0; c < g.image.channels; ++c) {
    S* channel = image + c * H * W;
    for (Index i = 0; i < k; ++i) {
      for (Index j = 0; j < k; ++j, src_row += Ho * Wo) {
        const ColumnRange range = valid_columns(g, j);
        for (Index oh = 0; oh < Ho; ++oh) {
          const Index h = oh * s - g.padding + i;
          if (h < 0 || h >= H) continue;
          const S* src = src_row + oh * Wo;
          S* dst = channel + h * W;
          const Index offset = j - g.padding;  // column ow adds into dst[ow * s + offset]
          for (Index ow = range.begin; ow < range.end; ++ow) dst[ow * s + offset] += src[ow];
        }
      }
    }
  }
}

template void im2col<float>(const float*, const PatchGeometry&, float*);
template void im2col<double>(const double*, const PatchGeometry&, double*);
template void col2im<float>(const float*, const PatchGeometry&, float*);
template void col2im<double>(const double*, const PatchGeometry&, double*);

}  // namespace corrmp::nn
