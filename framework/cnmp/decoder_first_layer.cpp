// The CNMP decoder's first layer, once per task for the representation (formulas in
// cnmp/decoder_first_layer.hpp).
#include "cnmp/decoder_first_layer.hpp"

#include "nn/gemm.hpp"

namespace corrmp {

template <class S>
DecoderFirstLayer<S>::DecoderFirstLayer(nn::Index representation_size, nn::Index query_size,
                                        nn::Index out, nn::Rng& rng)
    : linear_(representation_size + query_size, out, rng),
      representation_size_(representation_size) {}

template <class S>
void DecoderFirstLayer<S>::prepare(nn::Index tasks) {
  task_products_.resize(tasks, out_features());
  task_grads_.resize(tasks, out_features());
}

template <class S>
void DecoderFirstLayer<S>::forward_part(nn::ConstMatRef<S> r, nn::ConstMatRef<S> q,
                                        const std::vector<int>& target_counts, nn::MatRef<S> z,
                                        nn::Index first, nn::Index count) {
  if (count == 0) return;
  const auto& w = linear_.weight();
  const nn::Index rep = representation_size_, query = linear_.in_features() - rep;
  auto p = task_products_.shaped(r.rows(), out_features()).middleCols(first, count);
  nn::gemm<S>(r, nn::Op::kPlain, w.block(first, 0, count, rep), nn::Op::kTransposed, p, false,
              nn::gemm_scratch<S>());
  auto zp = z.middleCols(first, count);
  nn::gemm<S>(q, nn::Op::kPlain, w.block(first, rep, count, query), nn::Op::kTransposed, zp, false,
              nn::gemm_scratch<S>());
  const auto bias = linear_.bias().segment(first, count);
  nn::Index row = 0;
  for (size_t b = 0; b < target_counts.size(); ++b)
    for (int t = 0; t < target_counts[b]; ++t, ++row)
      zp.row(row) += p.row(static_cast<nn::Index>(b)) + bias;
}

template <class S>
void DecoderFirstLayer<S>::backward_params_part(nn::ConstMatRef<S> r, nn::ConstMatRef<S> q,
                                                nn::ConstMatRef<S> g,
                                                const std::vector<int>& target_counts,
                                                nn::Index first, nn::Index count) {
  if (count == 0) return;
  const nn::Index rep = representation_size_, query = linear_.in_features() - rep;
  auto s = task_grads_.shaped(r.rows(), out_features()).middleCols(first, count);
  const auto gp = g.middleCols(first, count);
  auto db = linear_.bias_grad().segment(first, count);
  nn::Index row = 0;
  for (size_t b = 0; b < target_counts.size(); ++b) {
    auto s_b = s.row(static_cast<nn::Index>(b));
    s_b.setZero();
    for (int t = 0; t < target_counts[b]; ++t, ++row) s_b += gp.row(row);
    db += s_b;
  }
  auto& dw = linear_.weight_grad();
  nn::gemm<S>(s, nn::Op::kTransposed, r, nn::Op::kPlain, dw.block(first, 0, count, rep), true,
              nn::gemm_scratch<S>());
  nn::gemm<S>(gp, nn::Op::kTransposed, q, nn::Op::kPlain, dw.block(first, rep, count, query), true,
              nn::gemm_scratch<S>());
}

template <class S>
void DecoderFirstLayer<S>::representation_grad_part(nn::MatRef<S> dr, nn::Index first,
                                                    nn::Index count) {
  if (count == 0) return;
  nn::gemm<S>(task_grads_.shaped(dr.rows(), out_features()), nn::Op::kPlain,
              linear_.weight().block(0, first, out_features(), count), nn::Op::kPlain,
              dr.middleCols(first, count), false, nn::gemm_scratch<S>());
}

template class DecoderFirstLayer<float>;
template class DecoderFirstLayer<double>;

}  // namespace corrmp
