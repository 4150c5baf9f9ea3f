// Tests of nn/thread_scratch.hpp: one buffer per slot and thread, and convolution layers that
// share them (nn/winograd_conv3x3.hpp, nn/winograd_stride2_conv3x3.hpp, nn/conv2d.hpp's im2col)
// computing, with calls of other layers between theirs and on other threads at once, exactly
// what each computes alone.
#include "nn/thread_scratch.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "nn/conv2d.hpp"
#include "nn/rng.hpp"
#include "nn/winograd_conv3x3.hpp"
#include "nn/winograd_stride2_conv3x3.hpp"

namespace corrmp::nn {
namespace {

TEST(ThreadScratch, OneBufferPerSlotAndThread) {
  Buffer<float>& input = thread_scratch<float>(Scratch::kInputSide);
  EXPECT_EQ(&input, &thread_scratch<float>(Scratch::kInputSide));
  EXPECT_NE(&input, &thread_scratch<float>(Scratch::kOutputSide));
  EXPECT_NE(&thread_scratch<float>(Scratch::kOutputSide),
            &thread_scratch<float>(Scratch::kGradients));
  const Buffer<float>* other = nullptr;
  std::thread([&] { other = &thread_scratch<float>(Scratch::kInputSide); }).join();
  EXPECT_NE(other, &input);
}

Mat<float> random_matrix(Index rows, Index cols, unsigned seed) {
  std::srand(seed);
  return Mat<float>::Random(rows, cols);
}

// Everything a layer's forward and backward give: output, weight, bias and input gradients.
struct Results {
  Mat<float> y, weight_grad, bias_grad, x_grad;
  bool operator==(const Results& o) const {
    return y == o.y && weight_grad == o.weight_grad && bias_grad == o.bias_grad &&
           x_grad == o.x_grad;
  }
};

// The layers of the test: Winograd stride 1 and stride 2, and im2col (nn/conv2d.hpp's path for
// fewer than kMinStride2WinogradChannels channels).
enum class Kind { kStride1, kStride2, kIm2col };

// A layer's shape, weights, inputs and output gradients, drawn once (Eigen's Random is not safe
// to call from two threads at once).
struct LayerRun {
  Kind kind;
  Index cin, cout, height, width, batch;
  Mat<float> w, b, x, dy;

  LayerRun(Kind k, Index in_channels, Index out_channels, Index h, Index wd, Index n, unsigned seed)
      : kind(k), cin(in_channels), cout(out_channels), height(h), width(wd), batch(n) {
    w = random_matrix(cout, cin * 9, seed);
    b = random_matrix(cout, 1, seed + 1);
    x = random_matrix(batch, in_size(), seed + 2);
    dy = random_matrix(batch, out_size(), seed + 3);
  }
  Index in_size() const { return cin * height * width; }
  Index out_size() const {
    const bool half = kind != Kind::kStride1;
    return half ? cout * ((height + 1) / 2) * ((width + 1) / 2) : cout * height * width;
  }

  // Forward, then `between`, then backward, on a layer of its own.
  template <class Between>
  Results run(Between&& between) const {
    Results r{Mat<float>(batch, out_size()), Mat<float>::Zero(cout, cin * 9),
              Mat<float>::Zero(cout, 1), Mat<float>(batch, in_size())};
    if (kind == Kind::kStride2) {
      WinogradStride2Conv3x3<float> layer(cin, cout, height, width);
      layer.convolve(w.data(), b.data(), x, r.y, /*relu=*/false);
      between();
      layer.convolve_backward(w.data(), x, dy, r.weight_grad.data(), r.bias_grad.data(),
                              r.x_grad.data(), in_size(), /*relu_input=*/false);
    } else if (kind == Kind::kStride1) {
      WinogradConv3x3<float> layer(cin, cout, height, width, KernelLayout::kConv);
      layer.forward(w.data(), b.data(), x, r.y);
      between();
      layer.backward(w.data(), x, dy, r.weight_grad.data(), r.bias_grad.data(), r.x_grad.data(),
                     in_size());
    } else {
      Rng rng(1);
      Conv2d<float> layer({cin, cout, 3, 2, 1}, height, width, rng);
      EXPECT_EQ(layer.algorithm(), ConvAlgorithm::kIm2col);
      layer.weight() = w;
      layer.bias() = b;
      layer.forward(x, r.y);
      between();
      layer.backward(x, dy, r.x_grad);
      r.weight_grad = layer.weight_grad();
      r.bias_grad = layer.bias_grad();
    }
    return r;
  }
};

TEST(ThreadScratch, LayersSharingItComputeWhatEachComputesAlone) {
  const LayerRun layers[] = {{Kind::kStride1, 3, 5, 9, 10, 3, 1},
                             {Kind::kStride2, 6, 4, 16, 16, 2, 5},
                             {Kind::kIm2col, 3, 4, 10, 12, 3, 9}};
  const auto nothing = [] {};
  std::vector<Results> alone;
  for (const LayerRun& layer : layers) alone.push_back(layer.run(nothing));
  // Every other layer's whole forward and backward between a layer's forward and its backward.
  for (size_t i = 0; i < 3; ++i)
    EXPECT_TRUE(layers[i].run([&] {
      for (size_t j = 0; j < 3; ++j)
        if (j != i) layers[j].run(nothing);
    }) == alone[i])
        << i;
  // Two layers on two threads at once, many times over.
  bool same[2] = {true, true};
  std::thread other([&] {
    for (int i = 0; i < 20; ++i) same[1] = same[1] && layers[1].run(nothing) == alone[1];
  });
  for (int i = 0; i < 20; ++i)
    for (size_t k : {size_t(0), size_t(2)}) same[0] = same[0] && layers[k].run(nothing) == alone[k];
  other.join();
  EXPECT_TRUE(same[0]);
  EXPECT_TRUE(same[1]);
}

}  // namespace
}  // namespace corrmp::nn
