// The parameter abstraction of corrmp::nn: a named view of one trainable tensor and its
// gradient, so the optimiser (nn/adam.hpp) and the model-file writer (nn/model_file.hpp) can
// iterate over any model without knowing its layers.
//
// A Parameter does not own memory. It points into the layer that created it and stays valid
// while that layer lives (moving the layer keeps it valid: Eigen moves heap storage by pointer).
// Values and gradients are contiguous in memory order of `shape` (row-major, PyTorch order).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "nn/tensor.hpp"

namespace corrmp::nn {

template <class S>
struct Parameter {
  std::string name;                 ///< e.g. "encoder.layers.0.weight"
  std::vector<std::int64_t> shape;  ///< e.g. {out, in} for a Linear weight
  S* value = nullptr;               ///< size() contiguous values
  S* grad = nullptr;                ///< size() contiguous gradient entries, same order

  Index size() const {
    Index n = 1;
    for (std::int64_t d : shape) n *= static_cast<Index>(d);
    return n;
  }
  Eigen::Map<Vec<S>> values() const { return Eigen::Map<Vec<S>>(value, size()); }
  Eigen::Map<Vec<S>> grads() const { return Eigen::Map<Vec<S>>(grad, size()); }
};

/// Sets every gradient to zero.
template <class S>
void zero_grad(const std::vector<Parameter<S>>& params) {
  for (const Parameter<S>& p : params) p.grads().setZero();
}

/// Total number of scalar parameters.
template <class S>
Index count_parameters(const std::vector<Parameter<S>>& params) {
  Index n = 0;
  for (const Parameter<S>& p : params) n += p.size();
  return n;
}

/// Appends `more` to `params` (for composing the parameter lists of several layers).
template <class S>
void append_parameters(std::vector<Parameter<S>>& params, const std::vector<Parameter<S>>& more) {
  params.insert(params.end(), more.begin(), more.end());
}

}  // namespace corrmp::nn
