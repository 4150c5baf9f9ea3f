// Verifies the central performance property of corrmp::nn: once warmed up with its largest
// batch, a CNMP-shaped training step (encoder Mlp, decoder Mlp, Gaussian NLL, Adam) performs no
// heap allocation, also when later batches are smaller.
//
// Allocations are counted by tests/support/allocation_counter.hpp.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>

#include "nn/adam.hpp"
#include "nn/buffer.hpp"
#include "nn/gaussian_nll.hpp"
#include "nn/mlp.hpp"
#include "nn/parameter.hpp"

#include "support/allocation_counter.hpp"

namespace corrmp::nn {
namespace {

TEST(NoAllocation, CounterSeesAllocations) {
  if (!corrmp::testing::kAllocationCounting)
    GTEST_SKIP() << "allocation counting is off under sanitizers";
  const long n = corrmp::testing::count_allocations([] {
    void* volatile p = std::malloc(64);
    std::free(p);
    Eigen::VectorXf* volatile v = new Eigen::VectorXf(100);
    delete v;
  });
  EXPECT_GE(n, 3);  // malloc, operator new, Eigen's aligned_malloc
}

// A CNMP-shaped update: encode observations, average, decode targets, NLL, backward, Adam.
class CnmpLikeStep {
 public:
  explicit CnmpLikeStep(Rng& rng)
      : encoder_({kObsDims, 128, 128, 128}, rng),
        decoder_({128 + 1, 128, 128, 128, 2 * kOutDims}, rng),
        adam_(all_parameters(), AdamOptions{}) {}

  float run(Index observations, Index targets, Rng& rng) {
    MatMap<float> obs = obs_.resize(observations, kObsDims);
    for (Index i = 0; i < obs.size(); ++i) obs.data()[i] = static_cast<float>(uniform01(rng));
    adam_.zero_grad();
    ConstMatMap<float> h = encoder_.forward(obs);
    MatMap<float> dec_in = dec_in_.resize(targets, 128 + 1);
    MatMap<float> latent = latent_.resize(1, 128);
    latent.noalias() = h.colwise().sum() / static_cast<float>(observations);
    dec_in.leftCols(128).rowwise() = latent.row(0);
    for (Index t = 0; t < targets; ++t) dec_in(t, 128) = static_cast<float>(t) / targets;
    ConstMatMap<float> out = decoder_.forward(dec_in);
    MatMap<float> target = target_.resize(targets, kOutDims);
    target.setConstant(0.5f);
    MatMap<float> d_out = d_out_.resize(targets, 2 * kOutDims);
    const float loss = nll_.value_and_grad(out.leftCols(kOutDims), out.rightCols(kOutDims), target,
                                           d_out.leftCols(kOutDims), d_out.rightCols(kOutDims));
    ConstMatMap<float> d_in = decoder_.backward(d_out);
    MatMap<float> d_h = d_h_.resize(observations, 128);
    latent.noalias() = d_in.leftCols(128).colwise().sum() / static_cast<float>(observations);
    d_h.rowwise() = latent.row(0);
    encoder_.backward_params_only(d_h);
    adam_.step();
    return loss;
  }

 private:
  static constexpr Index kObsDims = 4;
  static constexpr Index kOutDims = 3;

  std::vector<Parameter<float>> all_parameters() {
    std::vector<Parameter<float>> params = encoder_.parameters("encoder.");
    append_parameters(params, decoder_.parameters("decoder."));
    return params;
  }

  Mlp<float> encoder_;
  Mlp<float> decoder_;
  Adam<float> adam_;
  GaussianNll<float> nll_;
  Buffer<float> obs_, latent_, dec_in_, target_, d_out_, d_h_;
};

TEST(NoAllocation, WarmedUpCnmpTrainingStepDoesNotAllocate) {
  if (!corrmp::testing::kAllocationCounting)
    GTEST_SKIP() << "allocation counting is off under sanitizers";
  Rng rng(90);
  CnmpLikeStep step(rng);
  step.run(8, 8, rng);  // warm-up with the largest batch
  float loss = 0.0f;
  const long allocations = corrmp::testing::count_allocations([&] {
    for (Index n = 1; n <= 8; ++n) loss += step.run(n, 9 - n, rng);
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_TRUE(std::isfinite(loss));
}

}  // namespace
}  // namespace corrmp::nn
