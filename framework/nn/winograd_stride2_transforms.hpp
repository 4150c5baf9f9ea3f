// The 1-D maps of Winograd's stride-2 algorithm (formulas in nn/winograd_stride2_conv3x3.hpp):
// B9^T, its adjoint, A9^T, its adjoint, and G9's distinct rows and their adjoint, each on n lanes
// at once (the channels of one tile's pixels or terms), so that each is one loop that vectorises.
#pragma once

#include "nn/tensor.hpp"

namespace corrmp::nn::stride2 {

// The arrays a transform reads and writes are distinct, which the compiler cannot prove.
#if defined(__clang__)
#define CORRMP_INDEPENDENT_LANES _Pragma("clang loop vectorize(assume_safety)")
#elif defined(__GNUC__)
#define CORRMP_INDEPENDENT_LANES _Pragma("GCC ivdep")
#else
#define CORRMP_INDEPENDENT_LANES
#endif

// Each on n lanes at once: input k of lane c at in[k in_step + c], output k to
// out[k out_step + c].

// B9^T s (9 -> 9): the even inputs s_1 s_3 s_5 s_7, then F(4, 2)'s B^T on e_k = s_2k.
template <class S>
void input_9(Index n, const S* __restrict in, Index in_step, S* __restrict out, Index out_step) {
  CORRMP_INDEPENDENT_LANES
  for (Index c = 0; c < n; ++c) {
    const S e0 = in[c], e1 = in[2 * in_step + c], e2 = in[4 * in_step + c],
            e3 = in[6 * in_step + c], e4 = in[8 * in_step + c];
    out[c] = in[in_step + c];
    out[out_step + c] = in[3 * in_step + c];
    out[2 * out_step + c] = in[5 * in_step + c];
    out[3 * out_step + c] = in[7 * in_step + c];
    out[4 * out_step + c] = S(2) * (e0 - e2) + (e3 - e1);
    out[5 * out_step + c] = S(2) * e1 + (e2 - e3);
    out[6 * out_step + c] = S(3) * e2 - S(2) * e1 - e3;
    out[7 * out_step + c] = e3 - e1;
    out[8 * out_step + c] = S(2) * (e1 - e3) + (e4 - e2);
  }
}

// B9 d, the adjoint of input_9 (9 -> 9): output 0 added to what out holds with kAddFirst,
// outputs 1-8 with kAddRest; outputs not added overwrite out.
template <bool kAddFirst, bool kAddRest, class S>
void input_grad_9(Index n, const S* __restrict in, Index in_step, S* __restrict out,
                  Index out_step) {
  CORRMP_INDEPENDENT_LANES
  for (Index c = 0; c < n; ++c) {
    const S d4 = in[4 * in_step + c], d5 = in[5 * in_step + c], d6 = in[6 * in_step + c],
            d7 = in[7 * in_step + c], d8 = in[8 * in_step + c];
    const S r[9] = {S(2) * d4,
                    in[c],
                    S(2) * (d5 - d6 + d8) - (d4 + d7),
                    in[in_step + c],
                    (d5 - d8) + S(3) * d6 - S(2) * d4,
                    in[2 * in_step + c],
                    (d4 - d5) + (d7 - d6) - S(2) * d8,
                    in[3 * in_step + c],
                    d8};
    out[c] = kAddFirst ? out[c] + r[0] : r[0];
    for (int k = 1; k < 9; ++k)
      out[k * out_step + c] = kAddRest ? out[k * out_step + c] + r[k] : r[k];
  }
}

// A9^T m (9 -> 4).
template <class S>
void output_9(Index n, const S* __restrict in, Index in_step, S* __restrict out, Index out_step) {
  CORRMP_INDEPENDENT_LANES
  for (Index c = 0; c < n; ++c) {
    const S m5 = in[5 * in_step + c], m6 = in[6 * in_step + c], m7 = in[7 * in_step + c];
    const S sum = m5 + m6, diff = m5 - m6;
    out[c] = in[c] + in[4 * in_step + c] + sum + m7;
    out[out_step + c] = in[in_step + c] + diff + S(2) * m7;
    out[2 * out_step + c] = in[2 * in_step + c] + sum + S(4) * m7;
    out[3 * out_step + c] = in[3 * in_step + c] + diff + S(8) * m7 + in[8 * in_step + c];
  }
}

// A9 g, the adjoint of output_9 (4 -> 9).
template <class S>
void output_grad_4(Index n, const S* __restrict in, Index in_step, S* __restrict out,
                   Index out_step) {
  CORRMP_INDEPENDENT_LANES
  for (Index c = 0; c < n; ++c) {
    const S g0 = in[c], g1 = in[in_step + c], g2 = in[2 * in_step + c], g3 = in[3 * in_step + c];
    out[c] = g0;
    out[out_step + c] = g1;
    out[2 * out_step + c] = g2;
    out[3 * out_step + c] = g3;
    out[4 * out_step + c] = g0;
    out[5 * out_step + c] = (g0 + g2) + (g1 + g3);
    out[6 * out_step + c] = (g0 + g2) - (g1 + g3);
    out[7 * out_step + c] = g0 + S(2) * g1 + S(4) * g2 + S(8) * g3;
    out[8 * out_step + c] = g3;
  }
}

// The distinct entries of G9 w (3 -> 6): the middle tap (G9's rows 0-3), then F(4, 2)'s G on the
// outer taps (rows 4-8).
template <class S>
void weight_6(Index n, const S* __restrict in, Index in_step, S* __restrict out, Index out_step) {
  const S half(0.5), sixth(1.0 / 6.0), third(1.0 / 3.0);
  CORRMP_INDEPENDENT_LANES
  for (Index c = 0; c < n; ++c) {
    const S w0 = in[c], w2 = in[2 * in_step + c];
    out[c] = in[in_step + c];
    out[out_step + c] = half * w0;
    out[2 * out_step + c] = half * (w0 + w2);
    out[3 * out_step + c] = sixth * (w0 - w2);
    out[4 * out_step + c] = sixth * w0 + third * w2;
    out[5 * out_step + c] = w2;
  }
}

// The adjoint of weight_6 (6 -> 3), entry 0 holding the sum over G9's rows 0-3.
template <class S>
void weight_grad_6(Index n, const S* __restrict in, Index in_step, S* __restrict out,
                   Index out_step) {
  const S half(0.5), sixth(1.0 / 6.0), third(1.0 / 3.0);
  CORRMP_INDEPENDENT_LANES
  for (Index c = 0; c < n; ++c) {
    const S d2 = in[2 * in_step + c], d3 = in[3 * in_step + c], d4 = in[4 * in_step + c];
    out[c] = half * (in[in_step + c] + d2) + sixth * (d3 + d4);
    out[out_step + c] = in[c];
    out[2 * out_step + c] = half * d2 - sixth * d3 + third * d4 + in[5 * in_step + c];
  }
}

// Which of the 6 distinct entries of G9 w term xi of a dimension is.
constexpr int weight_entry(int xi) { return xi < 4 ? 0 : xi - 3; }

}  // namespace corrmp::nn::stride2
