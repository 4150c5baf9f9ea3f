// Tests of nn/thread_scratch.hpp: one buffer per slot and thread, and convolution layers that
// share them (Conv2d and ConvTranspose2d on each of their three paths: Winograd stride 1,
// Winograd stride 2, im2col) computing, with the slots overwritten between their forward and
// backward and with layers on another thread at once, exactly what each computes alone.
#include "nn/thread_scratch.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <thread>
#include <type_traits>
#include <vector>

#include "nn/conv2d.hpp"
#include "nn/conv_transpose2d.hpp"
#include "nn/rng.hpp"

namespace corrmp::nn {
namespace {

TEST(ThreadScratch, OneBufferPerSlotAndThread) {
  Buffer<float>& input = thread_scratch<float>(Scratch::kInputSide);
  EXPECT_EQ(&input, &thread_scratch<float>(Scratch::kInputSide));
  EXPECT_NE(&input, &thread_scratch<float>(Scratch::kOutputSide));
  EXPECT_NE(&thread_scratch<float>(Scratch::kOutputSide),
            &thread_scratch<float>(Scratch::kGradients));
  bool other_thread_has_its_own = false;
  std::thread([&] {
    other_thread_has_its_own = &thread_scratch<float>(Scratch::kInputSide) != &input;
  }).join();
  EXPECT_TRUE(other_thread_has_its_own);
}

// Everything a layer's forward and backward give: output, weight, bias and input gradients.
struct Results {
  Mat<float> y, weight_grad, bias_grad, x_grad;
  bool operator==(const Results& o) const {
    return y == o.y && weight_grad == o.weight_grad && bias_grad == o.bias_grad &&
           x_grad == o.x_grad;
  }
};

Mat<float> random_matrix(Index rows, Index cols, unsigned seed) {
  std::srand(seed);
  return Mat<float>::Random(rows, cols);
}

// A layer (Conv2d or ConvTranspose2d) with its weights, inputs and output gradients, drawn once
// (Eigen's Random is not safe to call from two threads at once); run() computes on a new layer.
template <class Layer>
struct LayerRun {
  using Options = std::conditional_t<std::is_same_v<Layer, Conv2d<float>>, Conv2dOptions,
                                     ConvTranspose2dOptions>;
  Options options;
  Index height, width, batch;
  Mat<float> weight, bias, x, dy;

  LayerRun(const Options& o, Index h, Index w, Index n, ConvAlgorithm expected, unsigned seed)
      : options(o), height(h), width(w), batch(n) {
    Layer layer = make();
    EXPECT_EQ(layer.algorithm(), expected);
    weight = random_matrix(layer.weight().rows(), layer.weight().cols(), seed);
    bias = random_matrix(layer.bias().size(), 1, seed + 1);
    x = random_matrix(batch, layer.input_shape().size(), seed + 2);
    dy = random_matrix(batch, layer.output_shape().size(), seed + 3);
  }
  Layer make() const {
    Rng rng(1);
    return Layer(options, height, width, rng);
  }
  // Forward, then `between`, then backward.
  Results run(const std::function<void()>& between) const {
    Layer layer = make();
    layer.weight() = weight;
    layer.bias() = bias;
    Results r{Mat<float>(batch, dy.cols()), {}, {}, Mat<float>(batch, x.cols())};
    layer.forward(x, r.y);
    between();
    layer.backward(x, dy, r.x_grad);
    r.weight_grad = layer.weight_grad();
    r.bias_grad = layer.bias_grad();
    return r;
  }
};

// NaN in every slot of this thread, up to its capacity.
void spoil_scratch() {
  for (Scratch slot :
       {Scratch::kInputSide, Scratch::kOutputSide, Scratch::kGradients, Scratch::kGemmOperand}) {
    Buffer<float>& buffer = thread_scratch<float>(slot);
    buffer.resize(1, buffer.capacity()).setConstant(std::numeric_limits<float>::quiet_NaN());
  }
}

TEST(ThreadScratch, LayersSharingItComputeWhatEachComputesAlone) {
  using Conv = LayerRun<Conv2d<float>>;
  using Transposed = LayerRun<ConvTranspose2d<float>>;
  const Conv convs[] = {
      {{3, 5, 3, 1, 1}, 9, 10, 3, ConvAlgorithm::kWinograd, 1},
      {{16, 16, 3, 2, 1}, 16, 16, 2, ConvAlgorithm::kWinogradStride2, 5},
      {{3, 4, 3, 2, 1}, 10, 12, 3, ConvAlgorithm::kIm2col, 9},
  };
  const Transposed transposed[] = {
      {{5, 3, 3, 1, 1, 0}, 9, 10, 3, ConvAlgorithm::kWinograd, 13},
      {{16, 16, 3, 2, 1, 1}, 8, 8, 2, ConvAlgorithm::kWinogradStride2, 17},
      {{4, 3, 3, 2, 1, 1}, 5, 6, 3, ConvAlgorithm::kIm2col, 21},
  };
  std::vector<std::function<Results(const std::function<void()>&)>> layers;
  for (const Conv& c : convs)
    layers.push_back([&c](const auto& between) { return c.run(between); });
  for (const Transposed& t : transposed)
    layers.push_back([&t](const auto& between) { return t.run(between); });
  const auto nothing = [] {};
  std::vector<Results> alone;
  for (const auto& layer : layers) alone.push_back(layer(nothing));
  for (size_t i = 0; i < layers.size(); ++i) {
    // The slots spoilt, or every other layer run, between a layer's forward and its backward.
    EXPECT_TRUE(layers[i](spoil_scratch) == alone[i]) << "layer " << i;
    EXPECT_TRUE(layers[i]([&] {
                  for (size_t j = 0; j < layers.size(); ++j)
                    if (j != i) layers[j](nothing);
                }) == alone[i])
        << "layer " << i;
  }
  // Half the layers on another thread at the same time, many times over.
  bool same[2] = {true, true};
  const auto run_half = [&](size_t half) {
    for (int round = 0; round < 10; ++round)
      for (size_t i = half; i < layers.size(); i += 2)
        same[half] = same[half] && layers[i](nothing) == alone[i];
  };
  std::thread other(run_half, 1);
  run_half(0);
  other.join();
  EXPECT_TRUE(same[0]);
  EXPECT_TRUE(same[1]);
}

}  // namespace
}  // namespace corrmp::nn
