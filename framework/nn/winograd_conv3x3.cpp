// Winograd F(4x4, 3x3) convolution (formulas in nn/winograd_conv3x3.hpp).
//
// Tile t of image n is (tile row ty, tile column tx), column n T + ty TW + tx of the chunk's
// matrices (T = TH TW tiles per image). Input side (6x6 patches overlapping by two pixels): each
// image row is split into the six patch columns of its 4-pixel tiles (split_patch_columns, one
// zero on the left) and stored by row phase in a plane with a zero row on top (plane_): entry
// (r, q) of every tile's patch is then one contiguous run over t, patch rows r and r + 4 one row
// of tiles apart. B^T runs along the patch rows over the whole plane at once, then along the
// patch columns over all tiles. Output side (4x4 tiles, no overlap): rows are split by column
// phase (split_row), entry (i, j) of every tile one run. Each 1-D transform is a loop over tiles
// that vectorises.
#include "nn/winograd_conv3x3.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "nn/channel_major.hpp"
#include "nn/gemm.hpp"
#include "nn/row_phases.hpp"

namespace corrmp::nn {
namespace {

// The chunk's matrices hold at most about this many values each (512 KB of floats).
constexpr Index kChunkValues = Index(1) << 17;
// Gap between the 36 term matrices of a chunk: the transforms write (or read) all 36 at the same
// offset, and matrices a power of two apart would fall into the same cache sets.
constexpr Index kTermGap = 16;

// G of the weight transform (nn/winograd_conv3x3.hpp).
constexpr double kG[6][3] = {
    {1.0 / 4, 0.0, 0.0},           {-1.0 / 6, -1.0 / 6, -1.0 / 6}, {-1.0 / 6, 1.0 / 6, -1.0 / 6},
    {1.0 / 24, 1.0 / 12, 1.0 / 6}, {1.0 / 24, -1.0 / 12, 1.0 / 6}, {0.0, 0.0, 1.0}};

// The arrays a transform reads and writes are distinct but lie in one buffer, so the compiler
// cannot prove that stores to them do not overlap across tiles; it is told so.
#if defined(__clang__)
#define CORRMP_INDEPENDENT_TILES _Pragma("clang loop vectorize(assume_safety)")
#elif defined(__GNUC__)
#define CORRMP_INDEPENDENT_TILES _Pragma("GCC ivdep")
#else
#define CORRMP_INDEPENDENT_TILES
#endif

// How a 1-D transform reads value j of tile t: rows `step` apart ...
template <class S>
struct Strided {
  const S* values;
  Index step;
  S operator()(int j, Index t) const { return values[j * step + t]; }
};

// ... or from rows split by phase: value j is in phase j mod 4, `shift` further on for j >= 4
// (the plane of WinogradConv3x3::transform_inputs).
template <class S>
struct Phased {
  const S* values;
  Index phase_stride, shift;
  S operator()(int j, Index t) const {
    return values[(j % 4) * phase_stride + (j / 4) * shift + t];
  }
};

// The 1-D transforms, each on n tiles at once (vectorised over tiles): value j of tile t is
// in(j, t), result k goes to out[k out_step + t].

// B^T d (6 -> 6).
template <class S, class In>
void input_1d(Index n, In in, S* __restrict out, Index out_step) {
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t < n; ++t) {
    const S d0 = in(0, t), d1 = in(1, t), d2 = in(2, t), d3 = in(3, t), d4 = in(4, t),
            d5 = in(5, t);
    const S even = d4 - S(4) * d2, odd = S(4) * d1 - d3;  // rows 1 and 2
    const S near = d4 - d2, far = S(2) * (d3 - d1);       // rows 3 and 4
    out[t] = S(4) * d0 - S(5) * d2 + d4;
    out[out_step + t] = even - odd;
    out[2 * out_step + t] = even + odd;
    out[3 * out_step + t] = near + far;
    out[4 * out_step + t] = near - far;
    out[5 * out_step + t] = S(4) * d1 - S(5) * d3 + d5;
  }
}

// B v, the adjoint of input_1d (6 -> 6), for value k of tile t at v[k v_step + t].
template <class S>
struct InputGrad {
  S e[6];
  InputGrad(const S* __restrict v, Index v_step, Index t) {
    const S v0 = v[t], v1 = v[v_step + t], v2 = v[2 * v_step + t], v3 = v[3 * v_step + t],
            v4 = v[4 * v_step + t], v5 = v[5 * v_step + t];
    e[0] = S(4) * v0;
    e[1] = S(4) * (v2 - v1 + v5) + S(2) * (v4 - v3);
    e[2] = -S(5) * v0 - S(4) * (v1 + v2) - (v3 + v4);
    e[3] = (v1 - v2) + S(2) * (v3 - v4) - S(5) * v5;
    e[4] = v0 + (v1 + v2) + (v3 + v4);
    e[5] = v5;
  }
};

template <class S>
void input_grad_1d(Index n, const S* __restrict in, Index in_step, S* __restrict out,
                   Index out_step) {
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t < n; ++t) {
    const InputGrad<S> g(in, in_step, t);
    for (int k = 0; k < 6; ++k) out[k * out_step + t] = g.e[k];
  }
}

// The same into rows split by phase, the adjoint of input_1d with Phased values: result r goes
// to out[(r mod 4) phase_stride + (r div 4) shift + t], results 4 and 5 added to what results 0
// and 1 wrote (for t < n - shift). Two loops, so that none writes an entry twice.
template <class S>
void input_grad_1d_phased(Index n, const S* __restrict in, Index in_step, S* __restrict out,
                          Index phase_stride, Index shift) {
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t < n; ++t) {
    const InputGrad<S> g(in, in_step, t);
    for (int r = 0; r < 4; ++r) out[r * phase_stride + t] = g.e[r];
  }
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t + shift < n; ++t) {
    const InputGrad<S> g(in, in_step, t);
    out[shift + t] += g.e[4];
    out[phase_stride + shift + t] += g.e[5];
  }
}

// A^T m (6 -> 4).
template <class S>
void output_1d(Index n, const S* __restrict in, Index in_step, S* __restrict out, Index out_step) {
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t < n; ++t) {
    const S m0 = in[t], m1 = in[in_step + t], m2 = in[2 * in_step + t], m3 = in[3 * in_step + t],
            m4 = in[4 * in_step + t], m5 = in[5 * in_step + t];
    const S sum12 = m1 + m2, diff12 = m1 - m2, sum34 = m3 + m4, diff34 = m3 - m4;
    out[t] = m0 + sum12 + sum34;
    out[out_step + t] = diff12 + S(2) * diff34;
    out[2 * out_step + t] = sum12 + S(4) * sum34;
    out[3 * out_step + t] = diff12 + S(8) * diff34 + m5;
  }
}

// A y, the adjoint of output_1d (4 -> 6).
template <class S>
void output_grad_1d(Index n, const S* __restrict in, Index in_step, S* __restrict out,
                    Index out_step) {
  CORRMP_INDEPENDENT_TILES
  for (Index t = 0; t < n; ++t) {
    const S y0 = in[t], y1 = in[in_step + t], y2 = in[2 * in_step + t], y3 = in[3 * in_step + t];
    const S even1 = y0 + y2, odd1 = y1 + y3, even2 = y0 + S(4) * y2, odd2 = S(2) * y1 + S(8) * y3;
    out[t] = y0;
    out[out_step + t] = even1 + odd1;
    out[2 * out_step + t] = even1 - odd1;
    out[3 * out_step + t] = even2 + odd2;
    out[4 * out_step + t] = even2 - odd2;
    out[5 * out_step + t] = y3;
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
      tile_rows_((height + kTile - 1) / kTile),
      tile_cols_((width + kTile - 1) / kTile),
      column_stride_((tile_rows_ + 1) * tile_cols_),
      block_(kPatch * column_stride_) {
  if (in_channels < 1 || out_channels < 1 || height < 1 || width < 1)
    throw std::invalid_argument("WinogradConv3x3: empty shape");
  plane_ = Vec<S>::Zero(4 * block_);
  sums_ = Vec<S>::Zero(4 * block_);
  rows_ = Vec<S>::Zero(kPatch * block_);
  row_grads_ = Vec<S>::Zero(kPatch * block_);
  for (Vec<S>& tiles : tiles_) tiles = Vec<S>::Zero(kPatch * kTile * tile_rows_ * tile_cols_);
  pair_scratch_ = Vec<S>::Zero(27 * in_channels);
}

template <class S>
Index WinogradConv3x3<S>::pair_offset(Index o, Index c) const {
  return 9 * (layout_ == KernelLayout::kConv ? o * in_channels_ + c : c * out_channels_ + o);
}

template <class S>
Index WinogradConv3x3<S>::term_stride(Index channels, Index columns) {
  return channels * columns + kTermGap;
}

template <class S>
void WinogradConv3x3<S>::transform_weights(const S* weight) {
  const size_t values = static_cast<size_t>(9 * in_channels_ * out_channels_);
  if (u_stamp_.matches(weight, values)) {
    u_data_ = u_.view().data();
    return;
  }
  if (weight_source_ != nullptr && weight_source_->u_stamp_.matches(weight, values)) {
    u_data_ = weight_source_->u_data_;
    return;
  }
  // Row xi: U_xi as Cout x Cin, row-major (and a gap).
  // One output channel's pairs at a time, each step a loop over the input channels c.
  MatMap<S> u = u_.resize(kTerms, term_stride(out_channels_, in_channels_));
  const Index cin = in_channels_;
  S* g = pair_scratch_.data();  // g_{o,c}[i][j] at g[(3 i + j) cin + c]
  S* t = g + 9 * cin;           // (G g_{o,c})[k][j] at t[(3 k + j) cin + c]
  for (Index o = 0; o < out_channels_; ++o) {
    const bool flipped = layout_ == KernelLayout::kTransposed;
    for (Index c = 0; c < cin; ++c) {  // the pair's 9 weights are contiguous
      const S* pair = weight + pair_offset(o, c);
      for (int e = 0; e < 9; ++e) g[e * cin + c] = pair[flipped ? 8 - e : e];
    }
    for (int k = 0; k < kPatch; ++k)  // t = G g
      for (int j = 0; j < 3; ++j)
        for (Index c = 0; c < cin; ++c)
          t[(3 * k + j) * cin + c] = S(kG[k][0]) * g[j * cin + c] +
                                     S(kG[k][1]) * g[(3 + j) * cin + c] +
                                     S(kG[k][2]) * g[(6 + j) * cin + c];
    for (int k = 0; k < kPatch; ++k)  // U = t G^T
      for (int l = 0; l < kPatch; ++l) {
        S* out = &u(kPatch * k + l, o * cin);
        for (Index c = 0; c < cin; ++c)
          out[c] = t[3 * k * cin + c] * S(kG[l][0]) + t[(3 * k + 1) * cin + c] * S(kG[l][1]) +
                   t[(3 * k + 2) * cin + c] * S(kG[l][2]);
      }
  }
  u_data_ = u.data();
  u_stamp_.set(weight, values);  // last: U is complete
}

template <class S>
Index WinogradConv3x3<S>::chunk_images(Index batch) const {
  const Index per_image = kTerms * std::max(in_channels_, out_channels_) * tile_rows_ * tile_cols_;
  return std::max<Index>(1, std::min(batch, kChunkValues / per_image));
}

template <class S>
S* WinogradConv3x3<S>::plane_row(Vec<S>& plane, Index y) const {
  return plane.data() + (y % 4) * block_ + (y / 4) * tile_cols_;
}

template <class S>
void WinogradConv3x3<S>::transform_inputs(const S* images, Index stride, Index count) {
  const Index TW = tile_cols_, T = tile_rows_ * TW, columns = count * T;
  const Index terms = term_stride(in_channels_, columns);
  S* v = input_terms().resize(kTerms, terms).data();
  for (Index n = 0; n < count; ++n)
    for (Index c = 0; c < in_channels_; ++c) {
      // Plane row h + 1 is image row h; rows 0 and past the image stay zero.
      const S* channel = images + n * stride + c * height_ * width_;
      for (Index h = 0; h < height_; ++h)
        split_patch_columns(channel + h * width_, width_, TW, plane_row(plane_, h + 1),
                            column_stride_);
      // B^T along the patch rows of all tiles at once (and a row of tiles past the image),
      // then along the patch columns.
      input_1d<S>(block_, Phased<S>{plane_.data(), block_, TW}, rows_.data(), block_);
      S* out = v + c * columns + n * T;  // term xi at out + xi terms
      for (int k = 0; k < kPatch; ++k)
        input_1d<S>(T, Strided<S>{rows_.data() + k * block_, column_stride_},
                    out + k * kPatch * terms, terms);
    }
}

template <class S>
void WinogradConv3x3<S>::transform_output_grads(const S* images, Index stride, Index count) {
  const Index TW = tile_cols_, T = tile_rows_ * TW, columns = count * T;
  const Index terms = term_stride(out_channels_, columns);
  S* dm = output_terms().resize(kTerms, terms).data();
  S* tiles = tiles_[0].data();         // the 4x4 tiles, entry (i, j) at tiles + (4 i + j) T
  S* columns_done = tiles_[1].data();  // A applied along each tile column: 6 x 4 per tile
  for (Index n = 0; n < count; ++n)
    for (Index o = 0; o < out_channels_; ++o) {
      const S* channel = images + n * stride + o * height_ * width_;
      for (Index h = 0; h < kTile * tile_rows_; ++h)
        split_row(h < height_ ? channel + h * width_ : nullptr, width_, TW,
                  tiles + (h % kTile) * kTile * T + (h / kTile) * TW, T);
      for (int j = 0; j < kTile; ++j)
        output_grad_1d(T, tiles + j * T, kTile * T, columns_done + j * T, kTile * T);
      S* out = dm + o * columns + n * T;
      for (int k = 0; k < kPatch; ++k)
        output_grad_1d(T, columns_done + k * kTile * T, T, out + k * kPatch * terms, terms);
    }
}

template <class S>
void WinogradConv3x3<S>::write_outputs(const S* bias, Index count, S* images, Index stride,
                                       bool relu) {
  const Index TW = tile_cols_, T = tile_rows_ * TW, columns = count * T;
  const Index terms = term_stride(out_channels_, columns), pixels = height_ * width_;
  const S* m = output_terms().view().data();
  S* columns_done = tiles_[0].data();  // A^T applied along each term column: 4 x 6 per tile
  S* tiles = tiles_[1].data();         // the 4x4 output tiles, entry (i, j) at tiles + (4 i + j) T
  const S floor = relu ? S(0) : -std::numeric_limits<S>::infinity();
  for (Index n = 0; n < count; ++n)
    for (Index o = 0; o < out_channels_; ++o) {
      const S* in = m + o * columns + n * T;
      for (int l = 0; l < kPatch; ++l)
        output_1d(T, in + l * terms, kPatch * terms, columns_done + l * T, kPatch * T);
      for (int i = 0; i < kTile; ++i)
        output_1d(T, columns_done + i * kPatch * T, T, tiles + i * kTile * T, T);
      S* __restrict channel = images + n * stride + o * height_ * width_;
      for (Index h = 0; h < height_; ++h)
        merge_row(tiles + (h % kTile) * kTile * T + (h / kTile) * TW, T, width_, TW,
                  channel + h * width_);
      // Once the channel is merged: reading a row right after merge_row's narrower stores
      // would stall on them (store forwarding fails).
      const S bias_o = bias[o];
      for (Index i = 0; i < pixels; ++i) channel[i] = std::max(channel[i] + bias_o, floor);
    }
}

template <class S>
void WinogradConv3x3<S>::write_input_grads(Index count, S* images, Index stride,
                                           const S* relu_inputs, Index input_stride) {
  const Index TW = tile_cols_, T = tile_rows_ * TW, columns = count * T;
  const Index terms = term_stride(in_channels_, columns), pixels = height_ * width_;
  const S* dv = input_terms().view().data();
  for (Index n = 0; n < count; ++n)
    for (Index c = 0; c < in_channels_; ++c) {
      // B along the patch columns (the rows of tiles past the image stay zero), then along the
      // patch rows into the plane, the overlapping rows added.
      const S* in = dv + c * columns + n * T;
      for (int k = 0; k < kPatch; ++k)
        input_grad_1d(T, in + k * kPatch * terms, terms, row_grads_.data() + k * block_,
                      column_stride_);
      input_grad_1d_phased(block_, row_grads_.data(), block_, sums_.data(), block_, TW);
      S* __restrict channel = images + n * stride + c * height_ * width_;
      for (Index h = 0; h < height_; ++h)
        merge_patch_columns(plane_row(sums_, h + 1), column_stride_, width_, TW,
                            channel + h * width_);
      if (relu_inputs == nullptr) continue;
      // Masked once the channel is merged, for the reason in write_outputs.
      const S* __restrict keep = relu_inputs + n * input_stride + c * height_ * width_;
      for (Index i = 0; i < pixels; ++i) channel[i] = keep[i] > S(0) ? channel[i] : S(0);
    }
}

template <class S>
void WinogradConv3x3<S>::forward(const S* weight, const S* bias, ConstMatRef<S> x, MatRef<S> y,
                                 bool relu) {
  transform_weights(weight);
  const Index batch = x.rows(), chunk = chunk_images(batch);
  const Index tiles = tile_rows_ * tile_cols_, cin = in_channels_, cout = out_channels_;
  Buffer<S>& scratch = gemm_scratch<S>();
  for (Index first = 0; first < batch; first += chunk) {
    const Index count = std::min(chunk, batch - first), columns = count * tiles;
    transform_inputs(x.row(first).data(), x.outerStride(), count);
    const Index v_terms = term_stride(cin, columns), m_terms = term_stride(cout, columns);
    const S* v_data = input_terms().view().data();
    S* m_data = output_terms().resize(kTerms, m_terms).data();
    for (int xi = 0; xi < kTerms; ++xi) {
      const ConstMatMap<S> u(u_data_ + xi * term_stride(cout, cin), cout, cin);
      const ConstMatMap<S> v(v_data + xi * v_terms, cin, columns);
      gemm<S>(u, Op::kPlain, v, Op::kPlain, MatMap<S>(m_data + xi * m_terms, cout, columns),
              /*accumulate=*/false, scratch);
    }
    write_outputs(bias, count, y.row(first).data(), y.outerStride(), relu);
  }
}

template <class S>
void WinogradConv3x3<S>::backward(const S* weight, ConstMatRef<S> x, ConstMatRef<S> dy,
                                  S* weight_grad, S* bias_grad, S* dx, Index dx_stride,
                                  bool relu_input) {
  const Index batch = x.rows(), chunk = chunk_images(batch);
  const Index tiles = tile_rows_ * tile_cols_, cin = in_channels_, cout = out_channels_;
  add_channel_sums(dy, cout, height_ * width_, bias_grad);
  if (batch == 0) return;
  transform_weights(weight);
  // The first chunk writes dU.
  MatMap<S> du = weight_grad_terms().resize(kTerms, term_stride(cout, cin));
  Buffer<S>& scratch = gemm_scratch<S>();
  for (Index first = 0; first < batch; first += chunk) {
    const Index count = std::min(chunk, batch - first), columns = count * tiles;
    transform_inputs(x.row(first).data(), x.outerStride(), count);
    transform_output_grads(dy.row(first).data(), dy.outerStride(), count);
    const Index v_terms = term_stride(cin, columns), m_terms = term_stride(cout, columns);
    S* v_data = input_terms().view().data();
    const S* m_data = output_terms().view().data();
    for (int xi = 0; xi < kTerms; ++xi) {
      const ConstMatMap<S> u(u_data_ + xi * term_stride(cout, cin), cout, cin);
      MatMap<S> v(v_data + xi * v_terms, cin, columns);
      const ConstMatMap<S> dm(m_data + xi * m_terms, cout, columns);
      gemm<S>(dm, Op::kPlain, v, Op::kTransposed, MatMap<S>(du.data() + xi * du.cols(), cout, cin),
              /*accumulate=*/first > 0, scratch);
      // V_xi is used up: it takes dV_xi.
      if (dx != nullptr)
        gemm<S>(u, Op::kTransposed, dm, Op::kPlain, v, /*accumulate=*/false, scratch);
    }
    if (dx != nullptr)
      write_input_grads(count, dx + first * dx_stride, dx_stride,
                        relu_input ? x.row(first).data() : nullptr, x.outerStride());
  }
  // dL/dg = G^T dU G for every channel pair, an output channel's pairs at a time.
  S* s = pair_scratch_.data();  // (G^T dU_{o,c})[i][l] at s[(6 i + l) cin + c]
  for (Index o = 0; o < cout; ++o) {
    for (int i = 0; i < 3; ++i)  // s = G^T dU
      for (int l = 0; l < kPatch; ++l)
        for (Index c = 0; c < cin; ++c) {
          S sum(0);
          for (int k = 0; k < kPatch; ++k) sum += S(kG[k][i]) * du(kPatch * k + l, o * cin + c);
          s[(kPatch * i + l) * cin + c] = sum;
        }
    S* dg = s + 18 * cin;        // dL/dg_{o,c}[i][j] at dg[(3 i + j) cin + c]
    for (int i = 0; i < 3; ++i)  // dg = s G
      for (int j = 0; j < 3; ++j)
        for (Index c = 0; c < cin; ++c) {
          S sum(0);
          for (int l = 0; l < kPatch; ++l) sum += s[(kPatch * i + l) * cin + c] * S(kG[l][j]);
          dg[(3 * i + j) * cin + c] = sum;
        }
    const bool flipped = layout_ == KernelLayout::kTransposed;
    for (Index c = 0; c < cin; ++c) {  // added to the pair's 9 contiguous gradients
      S* pair = weight_grad + pair_offset(o, c);
      for (int e = 0; e < 9; ++e) pair[flipped ? 8 - e : e] += dg[e * cin + c];
    }
  }
}

template class WinogradConv3x3<float>;
template class WinogradConv3x3<double>;

}  // namespace corrmp::nn
