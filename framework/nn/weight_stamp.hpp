// The weights a layer's transformed weights were computed from (nn/winograd_conv3x3.hpp,
// nn/winograd_stride2_conv3x3.hpp), so that the transform runs once per change of the weights:
// forward and backward of a training step, and the data-parallel replicas of a model
// (context/autoencoder/data_parallel_trainer.hpp), reuse it. Compared bit for bit, so that a NaN
// or a zero's sign counts as a change.
#pragma once

#include <cstddef>
#include <cstring>
#include <vector>

namespace corrmp::nn {

template <class S>
class WeightStamp {
 public:
  /// True if the stamp is of exactly these `count` weights.
  bool matches(const S* weight, size_t count) const {
    return values_.size() == count && std::memcmp(weight, values_.data(), count * sizeof(S)) == 0;
  }
  /// Stamps these weights.
  void set(const S* weight, size_t count) { values_.assign(weight, weight + count); }

 private:
  std::vector<S> values_;
};

}  // namespace corrmp::nn
