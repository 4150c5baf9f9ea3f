// Winograd F(2x2, 3x3) convolution (formulas in nn/winograd_conv3x3.hpp).
//
// Tile t of image n is (tile row ty, tile column tx), column n T + ty TW + tx of the chunk's
// matrices (T = TH TW tiles per image). The transforms run along a tile row with the tiles'
// columns split by parity: input patch column 2 tx - 1 + q is an odd image column for q = 0, 2
// and an even one for q = 1, 3, so every term of a transform is a contiguous run over tx and the
// loops vectorise.
#include "nn/winograd_conv3x3.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "nn/gemm.hpp"

namespace corrmp::nn {
namespace {

// The chunk's matrices hold at most about this many values each (512 KB of floats).
constexpr Index kChunkValues = Index(1) << 17;
// Gap between the 16 term matrices of a chunk: the transforms write (or read) all 16 at the same
// offset, and matrices a power of two apart would fall into the same cache sets.
constexpr Index kTermGap = 16;

// The 16 output (or input) arrays of a transform are distinct but lie in one buffer, so the
// compiler cannot prove that stores to them do not overlap across tiles; it is told so.
#if defined(__clang__)
#define CORRMP_INDEPENDENT_TILES _Pragma("clang loop vectorize(assume_safety)")
#elif defined(__GNUC__)
#define CORRMP_INDEPENDENT_TILES _Pragma("GCC ivdep")
#else
#define CORRMP_INDEPENDENT_TILES
#endif

// The tile transforms, each on n tiles at once (vectorised over tiles). Entry (r, q) of tile t's
// matrix is at base[(columns r + q) stride + t].

// V = B^T d B of the input patches, d[r][q] at patches[r row_stride + (q mod 2) parity_stride +
// q div 2 + t] (see transform_inputs). The kernels are written out term by term: loops over the
// entries would keep the compiler from vectorising over tiles.
template <class S>
void input_tiles(Index n, const S* __restrict patches, Index row_stride, Index parity_stride,
                 S* __restrict v, Index v_stride) {
  const S* __restrict rows[4][2];  // rows[r][parity]
  for (int r = 0; r < 4; ++r)
    for (int parity = 0; parity < 2; ++parity)
      rows[r][parity] = patches + r * row_stride + parity * parity_stride;
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t < n; ++t) {
    const S d00 = rows[0][0][t], d01 = rows[0][1][t], d02 = rows[0][0][t + 1],
            d03 = rows[0][1][t + 1];
    const S d10 = rows[1][0][t], d11 = rows[1][1][t], d12 = rows[1][0][t + 1],
            d13 = rows[1][1][t + 1];
    const S d20 = rows[2][0][t], d21 = rows[2][1][t], d22 = rows[2][0][t + 1],
            d23 = rows[2][1][t + 1];
    const S d30 = rows[3][0][t], d31 = rows[3][1][t], d32 = rows[3][0][t + 1],
            d33 = rows[3][1][t + 1];
    // a = B^T d
    const S a00 = d00 - d20, a10 = d10 + d20, a20 = d20 - d10, a30 = d10 - d30;
    const S a01 = d01 - d21, a11 = d11 + d21, a21 = d21 - d11, a31 = d11 - d31;
    const S a02 = d02 - d22, a12 = d12 + d22, a22 = d22 - d12, a32 = d12 - d32;
    const S a03 = d03 - d23, a13 = d13 + d23, a23 = d23 - d13, a33 = d13 - d33;
    // V = a B
    v[0 * v_stride + t] = a00 - a02;
    v[1 * v_stride + t] = a01 + a02;
    v[2 * v_stride + t] = a02 - a01;
    v[3 * v_stride + t] = a01 - a03;
    v[4 * v_stride + t] = a10 - a12;
    v[5 * v_stride + t] = a11 + a12;
    v[6 * v_stride + t] = a12 - a11;
    v[7 * v_stride + t] = a11 - a13;
    v[8 * v_stride + t] = a20 - a22;
    v[9 * v_stride + t] = a21 + a22;
    v[10 * v_stride + t] = a22 - a21;
    v[11 * v_stride + t] = a21 - a23;
    v[12 * v_stride + t] = a30 - a32;
    v[13 * v_stride + t] = a31 + a32;
    v[14 * v_stride + t] = a32 - a31;
    v[15 * v_stride + t] = a31 - a33;
  }
}

// B dV B^T, the adjoint of input_tiles' transform (4x4 -> 4x4).
template <class S>
void input_grad_tiles(Index n, const S* __restrict dv, Index dv_stride, S* __restrict dd,
                      Index dd_stride) {
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t < n; ++t) {
    const S v00 = dv[0 * dv_stride + t], v01 = dv[1 * dv_stride + t], v02 = dv[2 * dv_stride + t],
            v03 = dv[3 * dv_stride + t];
    const S v10 = dv[4 * dv_stride + t], v11 = dv[5 * dv_stride + t], v12 = dv[6 * dv_stride + t],
            v13 = dv[7 * dv_stride + t];
    const S v20 = dv[8 * dv_stride + t], v21 = dv[9 * dv_stride + t], v22 = dv[10 * dv_stride + t],
            v23 = dv[11 * dv_stride + t];
    const S v30 = dv[12 * dv_stride + t], v31 = dv[13 * dv_stride + t],
            v32 = dv[14 * dv_stride + t], v33 = dv[15 * dv_stride + t];
    // e = B dV
    const S e00 = v00, e10 = v10 - v20 + v30, e20 = v10 + v20 - v00, e30 = -v30;
    const S e01 = v01, e11 = v11 - v21 + v31, e21 = v11 + v21 - v01, e31 = -v31;
    const S e02 = v02, e12 = v12 - v22 + v32, e22 = v12 + v22 - v02, e32 = -v32;
    const S e03 = v03, e13 = v13 - v23 + v33, e23 = v13 + v23 - v03, e33 = -v33;
    // e B^T
    dd[0 * dd_stride + t] = e00;
    dd[1 * dd_stride + t] = e01 - e02 + e03;
    dd[2 * dd_stride + t] = e01 + e02 - e00;
    dd[3 * dd_stride + t] = -e03;
    dd[4 * dd_stride + t] = e10;
    dd[5 * dd_stride + t] = e11 - e12 + e13;
    dd[6 * dd_stride + t] = e11 + e12 - e10;
    dd[7 * dd_stride + t] = -e13;
    dd[8 * dd_stride + t] = e20;
    dd[9 * dd_stride + t] = e21 - e22 + e23;
    dd[10 * dd_stride + t] = e21 + e22 - e20;
    dd[11 * dd_stride + t] = -e23;
    dd[12 * dd_stride + t] = e30;
    dd[13 * dd_stride + t] = e31 - e32 + e33;
    dd[14 * dd_stride + t] = e31 + e32 - e30;
    dd[15 * dd_stride + t] = -e33;
  }
}

// Y = A^T M A (4x4 -> 2x2).
template <class S>
void output_tiles(Index n, const S* __restrict m, Index m_stride, S* __restrict y, Index y_stride) {
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t < n; ++t) {
    const S x00 = m[0 * m_stride + t], x01 = m[1 * m_stride + t], x02 = m[2 * m_stride + t],
            x03 = m[3 * m_stride + t];
    const S x10 = m[4 * m_stride + t], x11 = m[5 * m_stride + t], x12 = m[6 * m_stride + t],
            x13 = m[7 * m_stride + t];
    const S x20 = m[8 * m_stride + t], x21 = m[9 * m_stride + t], x22 = m[10 * m_stride + t],
            x23 = m[11 * m_stride + t];
    const S x30 = m[12 * m_stride + t], x31 = m[13 * m_stride + t], x32 = m[14 * m_stride + t],
            x33 = m[15 * m_stride + t];
    // r = A^T M
    const S r00 = x00 + x10 + x20, r10 = x10 - x20 - x30;
    const S r01 = x01 + x11 + x21, r11 = x11 - x21 - x31;
    const S r02 = x02 + x12 + x22, r12 = x12 - x22 - x32;
    const S r03 = x03 + x13 + x23, r13 = x13 - x23 - x33;
    // r A
    y[0 * y_stride + t] = r00 + r01 + r02;
    y[1 * y_stride + t] = r01 - r02 - r03;
    y[2 * y_stride + t] = r10 + r11 + r12;
    y[3 * y_stride + t] = r11 - r12 - r13;
  }
}

// dM = A dY A^T, the adjoint of output_tiles' transform (2x2 -> 4x4).
template <class S>
void output_grad_tiles(Index n, const S* __restrict dy, Index dy_stride, S* __restrict dm,
                       Index dm_stride) {
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t < n; ++t) {
    const S y00 = dy[t], y01 = dy[dy_stride + t], y10 = dy[2 * dy_stride + t],
            y11 = dy[3 * dy_stride + t];
    // p = A dY
    const S p00 = y00, p10 = y00 + y10, p20 = y00 - y10, p30 = -y10;
    const S p01 = y01, p11 = y01 + y11, p21 = y01 - y11, p31 = -y11;
    // p A^T
    dm[0 * dm_stride + t] = p00;
    dm[1 * dm_stride + t] = p00 + p01;
    dm[2 * dm_stride + t] = p00 - p01;
    dm[3 * dm_stride + t] = -p01;
    dm[4 * dm_stride + t] = p10;
    dm[5 * dm_stride + t] = p10 + p11;
    dm[6 * dm_stride + t] = p10 - p11;
    dm[7 * dm_stride + t] = -p11;
    dm[8 * dm_stride + t] = p20;
    dm[9 * dm_stride + t] = p20 + p21;
    dm[10 * dm_stride + t] = p20 - p21;
    dm[11 * dm_stride + t] = -p21;
    dm[12 * dm_stride + t] = p30;
    dm[13 * dm_stride + t] = p30 + p31;
    dm[14 * dm_stride + t] = p30 - p31;
    dm[15 * dm_stride + t] = -p31;
  }
}

// Splits an image row (`width` values, or zeros when row is null) by column parity, padded by
// one zero on the left: before[m] = row[2 m - 1] and at[m] = row[2 m] for m in [0, tiles], 0
// outside the row.
template <class S>
void split_padded(const S* row, Index width, Index tiles, S* __restrict before, S* __restrict at) {
  if (row == nullptr) {
    std::fill(before, before + tiles + 1, S(0));
    std::fill(at, at + tiles + 1, S(0));
  } else if (width % 2 == 0) {  // tiles = width / 2: no bounds inside the loop
    // One pass over the row's pairs: the row often comes from memory, not cache, and two
    // passes measured slower.
    before[0] = S(0);
    at[tiles] = S(0);
    S* __restrict odd = before + 1;
    for (Index m = 0; m < tiles; ++m) {
      at[m] = row[2 * m];
      odd[m] = row[2 * m + 1];
    }
  } else {
    for (Index m = 0; m <= tiles; ++m) {
      before[m] = m > 0 && 2 * m - 1 < width ? row[2 * m - 1] : S(0);
      at[m] = 2 * m < width ? row[2 * m] : S(0);
    }
  }
}

// Splits an image row by column parity: even[m] = row[2 m], odd[m] = row[2 m + 1] for m in
// [0, tiles), 0 outside the row (or everywhere when row is null).
template <class S>
void split(const S* row, Index width, Index tiles, S* __restrict even, S* __restrict odd) {
  if (row == nullptr) {
    std::fill(even, even + tiles, S(0));
    std::fill(odd, odd + tiles, S(0));
  } else if (width % 2 == 0) {
    for (Index m = 0; m < tiles; ++m) {
      even[m] = row[2 * m];
      odd[m] = row[2 * m + 1];
    }
  } else {
    for (Index m = 0; m < tiles; ++m) {
      even[m] = row[2 * m];
      odd[m] = 2 * m + 1 < width ? row[2 * m + 1] : S(0);
    }
  }
}

// One image row of the input gradient from the B dV B^T entries of the two tile rows that
// cover it (a: patch row r, b: patch row r + 2 of the tile row above, or zeros): column 2 m gets
// entries 1 of tile m and 3 of tile m - 1, column 2 m + 1 entries 2 of tile m and 0 of tile
// m + 1. Overwrites row; zeroes the entries where keep (the layer input after a ReLU) is not
// positive, unless keep is null.
template <class S>
void overlap_row(Index width, Index tiles, const S* const* a, const S* const* b,
                 const S* __restrict keep, S* __restrict row) {
  const auto out = [&](Index w, S value) {
    row[w] = keep == nullptr || keep[w] > S(0) ? value : S(0);
  };
  const S *a0 = a[0], *a1 = a[1], *a2 = a[2], *a3 = a[3];
  const S *b0 = b[0], *b1 = b[1], *b2 = b[2], *b3 = b[3];
  out(0, a1[0] + b1[0]);
  if (width > 1) out(1, a2[0] + b2[0] + (tiles > 1 ? a0[1] + b0[1] : S(0)));
  // The inner columns, in a loop without the test for keep so that it vectorises.
  const auto inner = [&](auto masked) {
    for (Index m = 1; m + 1 < tiles; ++m) {
      S even = a1[m] + b1[m] + a3[m - 1] + b3[m - 1];
      S odd = a2[m] + b2[m] + a0[m + 1] + b0[m + 1];
      if constexpr (decltype(masked)::value) {
        even = keep[2 * m] > S(0) ? even : S(0);
        odd = keep[2 * m + 1] > S(0) ? odd : S(0);
      }
      row[2 * m] = even;
      row[2 * m + 1] = odd;
    }
  };
  if (keep == nullptr)
    inner(std::false_type{});
  else
    inner(std::true_type{});
  if (tiles > 1) {
    const Index m = tiles - 1;
    out(2 * m, a1[m] + b1[m] + a3[m - 1] + b3[m - 1]);
    if (2 * m + 1 < width) out(2 * m + 1, a2[m] + b2[m]);
  }
}

}  // namespace

template <class S>
WinogradConv3x3<S>::WinogradConv3x3(Index in_channels, Index out_channels, Index height,
                                    Index width, KernelLayout layout)
    : in_channels_(in_channels),
      out_channels_(out_channels),
      height_(height),
      width_(width),
      layout_(layout),
      tile_rows_((height + 1) / 2),
      tile_cols_((width + 1) / 2),
      rows_(Vec<S>::Zero(32 * (tile_rows_ + 1) * (tile_cols_ + 1))) {
  if (in_channels < 1 || out_channels < 1 || height < 1 || width < 1)
    throw std::invalid_argument("WinogradConv3x3: empty shape");
}

template <class S>
Index WinogradConv3x3<S>::kernel_index(Index o, Index c, Index i, Index j) const {
  if (layout_ == KernelLayout::kConv) return (o * in_channels_ + c) * 9 + i * 3 + j;
  return (c * out_channels_ + o) * 9 + (2 - i) * 3 + (2 - j);
}

template <class S>
S* WinogradConv3x3<S>::scratch(Index k) {
  return rows_.data() + k * (tile_rows_ + 1) * (tile_cols_ + 1);
}

template <class S>
Index WinogradConv3x3<S>::term_stride(Index channels, Index columns) {
  return channels * columns + kTermGap;
}

template <class S>
void WinogradConv3x3<S>::transform_weights(const S* weight) {
  // Row xi: U_xi as Cout x Cin, row-major (and a gap).
  MatMap<S> u = u_.resize(kTerms, term_stride(out_channels_, in_channels_));
  const S half(0.5);
  for (Index o = 0; o < out_channels_; ++o)
    for (Index c = 0; c < in_channels_; ++c) {
      S g[3][3], t[4][3];
      for (Index i = 0; i < 3; ++i)
        for (Index j = 0; j < 3; ++j) g[i][j] = weight[kernel_index(o, c, i, j)];
      for (Index j = 0; j < 3; ++j) {  // t = G g
        t[0][j] = g[0][j];
        t[1][j] = half * (g[0][j] + g[1][j] + g[2][j]);
        t[2][j] = half * (g[0][j] - g[1][j] + g[2][j]);
        t[3][j] = g[2][j];
      }
      const Index pair = o * in_channels_ + c;
      for (Index r = 0; r < 4; ++r) {  // U = t G^T
        u(4 * r + 0, pair) = t[r][0];
        u(4 * r + 1, pair) = half * (t[r][0] + t[r][1] + t[r][2]);
        u(4 * r + 2, pair) = half * (t[r][0] - t[r][1] + t[r][2]);
        u(4 * r + 3, pair) = t[r][2];
      }
    }
}

template <class S>
Index WinogradConv3x3<S>::chunk_images(Index batch) const {
  const Index per_image = kTerms * std::max(in_channels_, out_channels_) * tile_rows_ * tile_cols_;
  return std::max<Index>(1, std::min(batch, kChunkValues / per_image));
}

template <class S>
void WinogradConv3x3<S>::transform_inputs(const S* images, Index stride, Index count) {
  const Index H = height_, W = width_, TW = tile_cols_, T = tile_rows_ * TW;
  const Index columns = count * T, terms = term_stride(in_channels_, columns);
  S* v = v_.resize(kTerms, terms).data();
  // Padded row k (image row k - 1, zero outside) split by parity into before_k and at_k (rows
  // TW + 1 apart): the patch of tile (ty, tx) has d[r][q] = before_{2 ty + r}[tx + q / 2] for
  // even q and at_{2 ty + r}[tx + q / 2] for odd q. The whole channel is split before any tile
  // reads it.
  const Index R = 2 * tile_rows_ + 2, row_stride = TW + 1, parity_stride = R * row_stride;
  S* before = scratch(0);  // R rows, then the R rows of `at`
  for (Index n = 0; n < count; ++n)
    for (Index c = 0; c < in_channels_; ++c) {
      const S* channel = images + n * stride + c * H * W;
      for (Index k = 0; k < R; ++k) {
        const Index h = k - 1;
        split_padded(h >= 0 && h < H ? channel + h * W : nullptr, W, TW, before + k * row_stride,
                     before + parity_stride + k * row_stride);
      }
      S* out = v + c * columns + n * T;  // term xi at out + xi terms
      for (Index ty = 0; ty < tile_rows_; ++ty)
        input_tiles(TW, before + 2 * ty * row_stride, row_stride, parity_stride, out + ty * TW,
                    terms);
    }
}

template <class S>
void WinogradConv3x3<S>::transform_output_grads(const S* images, Index stride, Index count) {
  const Index H = height_, W = width_, TW = tile_cols_, T = tile_rows_ * TW;
  const Index columns = count * T, terms = term_stride(out_channels_, columns);
  S* dm = m_.resize(kTerms, terms).data();
  // dy(a, b)[ty TW + tx] = dY at (2 ty + a, 2 tx + b) (0 past the image), arrays `split_stride`
  // apart.
  const Index split_stride = scratch(1) - scratch(0);
  const auto dy = [&](Index a, int b) { return scratch(2 * a + b); };
  for (Index n = 0; n < count; ++n)
    for (Index o = 0; o < out_channels_; ++o) {
      const S* channel = images + n * stride + o * H * W;
      for (Index h = 0; h < 2 * tile_rows_; ++h) {
        const Index offset = (h / 2) * TW;
        split(h < H ? channel + h * W : nullptr, W, TW, dy(h % 2, 0) + offset,
              dy(h % 2, 1) + offset);
      }
      output_grad_tiles(T, dy(0, 0), split_stride, dm + o * columns + n * T, terms);
    }
}

template <class S>
void WinogradConv3x3<S>::write_outputs(const S* bias, Index count, S* images, Index stride,
                                       bool relu) {
  const Index H = height_, W = width_, TW = tile_cols_, T = tile_rows_ * TW;
  const Index columns = count * T, terms = term_stride(out_channels_, columns);
  const S* m = m_.view().data();
  // y(a, b)[ty TW + tx] = output pixel (2 ty + a, 2 tx + b) before the bias.
  const Index y_stride = scratch(1) - scratch(0);
  const auto y = [&](int a, int b) { return scratch(2 * a + b); };
  for (Index n = 0; n < count; ++n)
    for (Index o = 0; o < out_channels_; ++o) {
      output_tiles(T, m + o * columns + n * T, terms, y(0, 0), y_stride);
      S* channel = images + n * stride + o * H * W;
      const S bias_o = bias[o];
      for (Index h = 0; h < H; ++h) {
        S* __restrict row = channel + h * W;
        const S* ye = y(h % 2, 0) + (h / 2) * TW;
        const S* yo = y(h % 2, 1) + (h / 2) * TW;
        const S floor = relu ? S(0) : -std::numeric_limits<S>::infinity();
        for (Index mm = 0; mm < W / 2; ++mm) {
          row[2 * mm] = std::max(ye[mm] + bias_o, floor);
          row[2 * mm + 1] = std::max(yo[mm] + bias_o, floor);
        }
        if (W % 2 == 1) row[W - 1] = std::max(ye[TW - 1] + bias_o, floor);
      }
    }
}

template <class S>
void WinogradConv3x3<S>::write_input_grads(Index count, S* images, Index stride,
                                           const S* relu_inputs, Index input_stride) {
  const Index H = height_, W = width_, TW = tile_cols_, T = tile_rows_ * TW;
  const Index columns = count * T, terms = term_stride(in_channels_, columns);
  const S* dv = v_.view().data();
  // f(r, q)[ty TW + tx] = (B dV B^T)[r][q] of tile (ty, tx), the gradient of input pixel
  // (2 ty - 1 + r, 2 tx - 1 + q), for all tiles of a channel before they are added up.
  const Index f_stride = scratch(1) - scratch(0);
  const auto f = [&](int r, int q) { return scratch(4 * r + q); };
  S* zeros = scratch(16);
  std::fill(zeros, zeros + TW + 1, S(0));
  for (Index n = 0; n < count; ++n)
    for (Index c = 0; c < in_channels_; ++c) {
      input_grad_tiles(T, dv + c * columns + n * T, terms, f(0, 0), f_stride);
      S* channel = images + n * stride + c * H * W;
      const S* input = relu_inputs ? relu_inputs + n * input_stride + c * H * W : nullptr;
      for (Index h = 0; h < H; ++h) {
        // Padded row h + 1 is patch row r of tile row (h + 1) / 2 and patch row r + 2 of the
        // tile row above, r = (h + 1) mod 2.
        const Index below = (h + 1) / 2, above = below - 1, r = (h + 1) % 2;
        const S* a[4];
        const S* b[4];
        for (int q = 0; q < 4; ++q) {
          a[q] = below < tile_rows_ ? f(r, q) + below * TW : zeros;
          b[q] = above >= 0 ? f(r + 2, q) + above * TW : zeros;
        }
        overlap_row(W, TW, a, b, input ? input + h * W : nullptr, channel + h * W);
      }
    }
}

template <class S>
void WinogradConv3x3<S>::forward(const S* weight, const S* bias, ConstMatRef<S> x, MatRef<S> y,
                                 bool relu) {
  transform_weights(weight);
  const Index batch = x.rows(), chunk = chunk_images(batch);
  const Index tiles = tile_rows_ * tile_cols_, cin = in_channels_, cout = out_channels_;
  for (Index first = 0; first < batch; first += chunk) {
    const Index count = std::min(chunk, batch - first), columns = count * tiles;
    transform_inputs(x.row(first).data(), x.outerStride(), count);
    const Index v_terms = term_stride(cin, columns), m_terms = term_stride(cout, columns);
    m_.resize(kTerms, m_terms);
    for (int xi = 0; xi < kTerms; ++xi) {
      const ConstMatMap<S> u(u_.view().data() + xi * u_.cols(), cout, cin);
      const ConstMatMap<S> v(v_.view().data() + xi * v_terms, cin, columns);
      gemm<S>(u, Op::kPlain, v, Op::kPlain,
              MatMap<S>(m_.view().data() + xi * m_terms, cout, columns),
              /*accumulate=*/false, transposed_);
    }
    write_outputs(bias, count, y.row(first).data(), y.outerStride(), relu);
  }
}

template <class S>
void WinogradConv3x3<S>::backward(const S* weight, ConstMatRef<S> x, ConstMatRef<S> dy,
                                  S* weight_grad, S* bias_grad, S* dx, Index dx_stride,
                                  bool relu_input) {
  transform_weights(weight);
  const Index batch = x.rows(), chunk = chunk_images(batch);
  const Index tiles = tile_rows_ * tile_cols_, cin = in_channels_, cout = out_channels_;
  MatMap<S> du = du_.resize(kTerms, term_stride(cout, cin));  // like U
  du.setZero();
  for (Index n = 0; n < batch; ++n)
    for (Index o = 0; o < cout; ++o)
      bias_grad[o] +=
          ConstMatMap<S>(dy.row(n).data() + o * height_ * width_, 1, height_ * width_).sum();
  for (Index first = 0; first < batch; first += chunk) {
    const Index count = std::min(chunk, batch - first), columns = count * tiles;
    transform_inputs(x.row(first).data(), x.outerStride(), count);
    transform_output_grads(dy.row(first).data(), dy.outerStride(), count);
    const Index v_terms = term_stride(cin, columns), m_terms = term_stride(cout, columns);
    for (int xi = 0; xi < kTerms; ++xi) {
      const ConstMatMap<S> u(u_.view().data() + xi * u_.cols(), cout, cin);
      MatMap<S> v(v_.view().data() + xi * v_terms, cin, columns);
      const ConstMatMap<S> dm(m_.view().data() + xi * m_terms, cout, columns);
      gemm<S>(dm, Op::kPlain, v, Op::kTransposed, MatMap<S>(du.data() + xi * du.cols(), cout, cin),
              /*accumulate=*/true, transposed_);
      // V_xi is used up: it takes dV_xi.
      if (dx != nullptr)
        gemm<S>(u, Op::kTransposed, dm, Op::kPlain, v, /*accumulate=*/false, transposed_);
    }
    if (dx != nullptr)
      write_input_grads(count, dx + first * dx_stride, dx_stride,
                        relu_input ? x.row(first).data() : nullptr, x.outerStride());
  }
  // dL/dg = G^T dU G for every channel pair.
  const S half(0.5);
  for (Index o = 0; o < cout; ++o)
    for (Index c = 0; c < cin; ++c) {
      const Index pair = o * cin + c;
      S d[4][4], s[3][4];
      for (int xi = 0; xi < kTerms; ++xi) d[xi / 4][xi % 4] = du(xi, pair);
      for (int q = 0; q < 4; ++q) {  // s = G^T dU
        s[0][q] = d[0][q] + half * (d[1][q] + d[2][q]);
        s[1][q] = half * (d[1][q] - d[2][q]);
        s[2][q] = half * (d[1][q] + d[2][q]) + d[3][q];
      }
      for (Index i = 0; i < 3; ++i) {  // dg = s G
        weight_grad[kernel_index(o, c, i, 0)] += s[i][0] + half * (s[i][1] + s[i][2]);
        weight_grad[kernel_index(o, c, i, 1)] += half * (s[i][1] - s[i][2]);
        weight_grad[kernel_index(o, c, i, 2)] += half * (s[i][1] + s[i][2]) + s[i][3];
      }
    }
}

template class WinogradConv3x3<float>;
template class WinogradConv3x3<double>;

}  // namespace corrmp::nn
