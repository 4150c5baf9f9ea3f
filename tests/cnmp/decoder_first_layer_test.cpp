// Tests of the CNMP decoder's first layer computed once per task: the same outputs and
// gradients as a Linear layer on the repeated rows [r_b, q_t], and the same bits whatever the
// columns each call computes.
#include "cnmp/decoder_first_layer.hpp"

#include <gtest/gtest.h>

#include "nn/gemm.hpp"
#include "nn/gradient_check.hpp"

namespace corrmp {
namespace {

using MatD = nn::Mat<double>;

constexpr nn::Index kRepresentation = 5, kQuery = 3, kOut = 7;
const std::vector<int> kTargetCounts{2, 0, 3, 1};  // a task without targets included

// The rows [r_b, q_t] the layer stands for, task b repeated once per target.
template <class S>
nn::Mat<S> repeated_rows(const nn::Mat<S>& r, const nn::Mat<S>& q) {
  nn::Mat<S> rows(q.rows(), kRepresentation + kQuery);
  nn::Index row = 0;
  for (size_t b = 0; b < kTargetCounts.size(); ++b)
    for (int t = 0; t < kTargetCounts[b]; ++t, ++row) {
      rows.row(row).leftCols(kRepresentation) = r.row(static_cast<nn::Index>(b));
      rows.row(row).rightCols(kQuery) = q.row(row);
    }
  return rows;
}

TEST(DecoderFirstLayer, GivesTheLinearLayersOutputsAndGradientsOnTheRepeatedRows) {
  nn::Rng init(3), reference_init(3), data(4);
  DecoderFirstLayer<double> layer(kRepresentation, kQuery, kOut, init);
  nn::Linear<double> linear(kRepresentation + kQuery, kOut, reference_init);  // the same draws
  const MatD r = nn::testing::random_matrix(4, kRepresentation, data);
  const MatD q = nn::testing::random_matrix(6, kQuery, data);
  const MatD g = nn::testing::random_matrix(6, kOut, data);
  const MatD rows = repeated_rows(r, q);

  layer.prepare(r.rows());
  MatD z(6, kOut), expected_z(6, kOut);
  layer.forward_part(r, q, kTargetCounts, z, 0, kOut);
  linear.forward(rows, expected_z);
  EXPECT_LT((z - expected_z).cwiseAbs().maxCoeff(), 1e-12);

  layer.backward_params_part(r, q, g, kTargetCounts, 0, kOut);
  MatD dr(4, kRepresentation), d_rows(6, kRepresentation + kQuery);
  layer.representation_grad_part(dr, 0, kRepresentation);
  linear.backward(rows, g, d_rows);
  const auto params = layer.parameters("");
  EXPECT_LT((params[0].grads() - Eigen::Map<const Eigen::VectorXd>(linear.weight_grad().data(),
                                                                   linear.weight_grad().size()))
                .cwiseAbs()
                .maxCoeff(),
            1e-12);
  EXPECT_LT((params[1].grads() - linear.bias_grad().transpose()).cwiseAbs().maxCoeff(), 1e-12);
  // dL/dr_b: the sum of the repeated rows' input gradients over task b's targets (zero for a
  // task without targets).
  nn::Index row = 0;
  for (size_t b = 0; b < kTargetCounts.size(); ++b) {
    const int m = kTargetCounts[b];
    const Eigen::RowVectorXd expected =
        d_rows.middleRows(row, m).leftCols(kRepresentation).colwise().sum();
    EXPECT_LT((dr.row(static_cast<nn::Index>(b)) - expected).cwiseAbs().maxCoeff(), 1e-12) << b;
    row += m;
  }
}

TEST(DecoderFirstLayer, ColumnsComputedInPartsAreTheWholeCallsBits) {
  if (!nn::gemm_float_split_exact()) GTEST_SKIP() << "float products run on Eigen in this build";
  nn::Rng init_whole(3), init_parts(3), data(4);
  DecoderFirstLayer<float> whole(kRepresentation, kQuery, kOut, init_whole);
  DecoderFirstLayer<float> parts(kRepresentation, kQuery, kOut, init_parts);
  const nn::Mat<float> r = nn::Mat<float>::Random(4, kRepresentation);
  const nn::Mat<float> q = nn::Mat<float>::Random(6, kQuery);
  const nn::Mat<float> g = nn::Mat<float>::Random(6, kOut);
  nn::Mat<float> z_whole(6, kOut), z_parts(6, kOut), dr_whole(4, kRepresentation),
      dr_parts(4, kRepresentation);
  whole.prepare(4);
  parts.prepare(4);
  whole.forward_part(r, q, kTargetCounts, z_whole, 0, kOut);
  whole.backward_params_part(r, q, g, kTargetCounts, 0, kOut);
  whole.representation_grad_part(dr_whole, 0, kRepresentation);
  for (const auto& [first, count] : {std::pair<int, int>{0, 3}, {3, 4}}) {
    parts.forward_part(r, q, kTargetCounts, z_parts, first, count);
    parts.backward_params_part(r, q, g, kTargetCounts, first, count);
  }
  for (const auto& [first, count] : {std::pair<int, int>{0, 2}, {2, 3}})
    parts.representation_grad_part(dr_parts, first, count);
  EXPECT_EQ(z_whole, z_parts);
  EXPECT_EQ(dr_whole, dr_parts);
  const auto a = whole.parameters(""), b = parts.parameters("");
  for (size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k].grads(), b[k].grads()) << a[k].name;
}

}  // namespace
}  // namespace corrmp
