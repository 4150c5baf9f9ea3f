// Mean squared error (formulas in nn/mse_loss.hpp).
#include "nn/mse_loss.hpp"

#include <stdexcept>

#include "nn/check.hpp"

namespace corrmp::nn {

template <class S>
S MseLoss<S>::value(ConstMatRef<S> prediction, ConstMatRef<S> target) const {
  check_shape("MseLoss", "target", target, prediction.rows(), prediction.cols());
  if (prediction.size() == 0) throw std::invalid_argument("MseLoss: empty batch");
  double sum = 0.0;
  for (Index i = 0; i < prediction.rows(); ++i)
    sum += (prediction.row(i) - target.row(i)).template cast<double>().squaredNorm();
  return static_cast<S>(sum / static_cast<double>(prediction.size()));
}

template <class S>
S MseLoss<S>::value_and_grad(ConstMatRef<S> prediction, ConstMatRef<S> target,
                             MatRef<S> d_prediction) const {
  const S loss = value(prediction, target);
  check_shape("MseLoss", "d_prediction", d_prediction, prediction.rows(), prediction.cols());
  const S scale = static_cast<S>(2.0 / static_cast<double>(prediction.size()));
  d_prediction = scale * (prediction - target);
  return loss;
}

template class MseLoss<float>;
template class MseLoss<double>;

}  // namespace corrmp::nn
