// Multi-layer perceptron (formulas in nn/mlp.hpp).
#include "nn/mlp.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "nn/activation.hpp"
#include "nn/check.hpp"
#include "nn/relu_fusion.hpp"

namespace corrmp::nn {

template <class S>
Mlp<S>::Mlp(std::vector<Index> sizes, Rng& rng) : sizes_(std::move(sizes)) {
  if (sizes_.size() < 2) throw std::invalid_argument("Mlp: sizes needs at least {in, out}");
  layers_.reserve(sizes_.size() - 1);
  for (std::size_t i = 0; i + 1 < sizes_.size(); ++i)
    layers_.emplace_back(sizes_[i], sizes_[i + 1], rng);
  outputs_.resize(layers_.size());
}

template <class S>
ConstMatMap<S> Mlp<S>::forward(ConstMatRef<S> x) {
  check_shape("Mlp::forward", "x", x, x.rows(), input_size());
  const Index n = x.rows();
  input_.resize(n, input_size()) = x;
  const Relu<S> relu;
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    MatMap<S> out = outputs_[i].resize(n, sizes_[i + 1]);
    layers_[i].forward(layer_input(i), out);
    if (i + 1 < layers_.size()) relu.forward(out, out);
  }
  return output();
}

template <class S>
void Mlp<S>::backward_layer(std::size_t i, ConstMatRef<S> g_i, bool input_grad,
                            Buffer<S>& dx_buffer) {
  if (!input_grad) {
    layers_[i].accumulate_param_grad(layer_input(i), g_i);
    return;
  }
  MatMap<S> dx = dx_buffer.resize(g_i.rows(), sizes_[i]);
  layers_[i].backward(layer_input(i), g_i, dx);
  if (i > 0) Relu<S>().backward(outputs_[i - 1].view(), dx, dx);
}

template <class S>
int Mlp<S>::run_backward(ConstMatRef<S> dy, bool input_grad) {
  check_shape("Mlp::backward", "dy", dy, input_.rows(), output_size());
  std::size_t i = layers_.size() - 1;
  backward_layer(i, dy, input_grad || i > 0, grads_[0]);
  int current = 0;  // grads_[current] holds dL/da_i * relu'(a_i) for the next layer down
  while (i-- > 0) {
    backward_layer(i, std::as_const(grads_[current]).view(), input_grad || i > 0,
                   grads_[1 - current]);
    current = 1 - current;
  }
  return current;
}

template <class S>
ConstMatMap<S> Mlp<S>::backward(ConstMatRef<S> dy) {
  return std::as_const(grads_[run_backward(dy, true)]).view();
}

template <class S>
void Mlp<S>::backward_params_only(ConstMatRef<S> dy) {
  run_backward(dy, false);
}

template <class S>
void Mlp<S>::prepare(Index rows) {
  input_.resize(rows, input_size());
  Index widest = input_size();
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    outputs_[i].resize(rows, sizes_[i + 1]);
    widest = std::max(widest, sizes_[i + 1]);
  }
  for (Buffer<S>& g : grads_) g.resize(rows, widest);
}

template <class S>
void Mlp<S>::forward_part(const Team& team) {
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    MatMap<S> out = outputs_[i].view();
    const auto [first, count] = team.share(sizes_[i + 1]);
    layers_[i].forward_part(layer_input(i), out, first, count);
    if (i + 1 < layers_.size() && count > 0) relu_in_place(out.middleCols(first, count));
    team.sync();
  }
}

template <class S>
ConstMatMap<S> Mlp<S>::backward_part(ConstMatRef<S> dy, bool input_grad, const Team& team) {
  const Index rows = input_.rows();
  check_shape("Mlp::backward_part", "dy", dy, rows, output_size());
  int current = -1;  // grads_[current] holds g_i (dy for the last layer)
  for (std::size_t i = layers_.size(); i-- > 0;) {
    const ConstMatRef<S> g_i =
        current < 0 ? dy : ConstMatRef<S>(grads_[current].shaped(rows, sizes_[i + 1]));
    const auto [first, count] = team.share(sizes_[i + 1]);
    layers_[i].weight_grad_part(layer_input(i), g_i, first, count);
    if (team.member == 0) layers_[i].accumulate_bias_grad(g_i);
    if (input_grad || i > 0) {
      const int next = current < 0 ? 0 : 1 - current;
      MatMap<S> dx = grads_[next].shaped(rows, sizes_[i]);
      const auto [in_first, in_count] = team.share(sizes_[i]);
      layers_[i].input_grad_part(g_i, dx, in_first, in_count);
      if (i > 0 && in_count > 0) {
        auto part = dx.middleCols(in_first, in_count);
        Relu<S>().backward(outputs_[i - 1].view().middleCols(in_first, in_count), part, part);
      }
      current = next;
    }
    team.sync();
  }
  if (!input_grad) return ConstMatMap<S>(nullptr, 0, 0);
  return ConstMatMap<S>(grads_[current].shaped(rows, input_size()).data(), rows, input_size());
}

template <class S>
std::vector<Parameter<S>> Mlp<S>::parameters(const std::string& prefix, Index first_number) {
  std::vector<Parameter<S>> params;
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    const std::string number = std::to_string(first_number + static_cast<Index>(i));
    append_parameters(params, layers_[i].parameters(prefix + "layers." + number + "."));
  }
  return params;
}

template <class S>
Index Mlp<S>::num_parameters() const {
  Index n = 0;
  for (const Linear<S>& layer : layers_) n += layer.num_parameters();
  return n;
}

template class Mlp<float>;
template class Mlp<double>;

}  // namespace corrmp::nn
