// Tests of nn/thread_scratch.hpp: one buffer per slot and thread, and convolution layers that
// share them (nn/winograd_conv3x3.hpp, nn/winograd_stride2_conv3x3.hpp) computing, with calls of
// other layers between theirs and on other threads at once, exactly what each computes alone.
#include "nn/thread_scratch.hpp"

#include <gtest/gtest.h>

#include <thread>

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

// A layer's shape, weights, inputs and output gradients, drawn once (Eigen's Random is not safe
// to call from two threads at once).
struct LayerRun {
  Index cin, cout, height, width, batch;
  bool stride2;
  Mat<float> w, b, x, dy;

  LayerRun(Index in_channels, Index out_channels, Index h, Index wd, Index n, bool half,
           unsigned seed)
      : cin(in_channels), cout(out_channels), height(h), width(wd), batch(n), stride2(half) {
    w = random_matrix(cout, cin * 9, seed);
    b = random_matrix(cout, 1, seed + 1);
    x = random_matrix(batch, in_size(), seed + 2);
    dy = random_matrix(batch, out_size(), seed + 3);
  }
  Index in_size() const { return cin * height * width; }
  Index out_size() const {
    return stride2 ? cout * ((height + 1) / 2) * ((width + 1) / 2) : cout * height * width;
  }

  // Forward, then `between`, then backward, on a layer of its own.
  template <class Between>
  Results run(Between&& between) const {
    Results r{Mat<float>(batch, out_size()), Mat<float>::Zero(cout, cin * 9),
              Mat<float>::Zero(cout, 1), Mat<float>(batch, in_size())};
    if (stride2) {
      WinogradStride2Conv3x3<float> layer(cin, cout, height, width);
      layer.convolve(w.data(), b.data(), x, r.y, /*relu=*/false);
      between();
      layer.convolve_backward(w.data(), x, dy, r.weight_grad.data(), r.bias_grad.data(),
                              r.x_grad.data(), in_size(), /*relu_input=*/false);
    } else {
      WinogradConv3x3<float> layer(cin, cout, height, width, KernelLayout::kConv);
      layer.forward(w.data(), b.data(), x, r.y);
      between();
      layer.backward(w.data(), x, dy, r.weight_grad.data(), r.bias_grad.data(), r.x_grad.data(),
                     in_size());
    }
    return r;
  }
};

TEST(ThreadScratch, LayersSharingItComputeWhatEachComputesAlone) {
  // 3 images of 9 x 10 (chunks cut the batch), and 16 x 16 images to 8 x 8.
  const LayerRun stride1(3, 5, 9, 10, 3, /*half=*/false, 1), stride2(6, 4, 16, 16, 2, true, 5);
  const auto nothing = [] {};
  const Results stride1_alone = stride1.run(nothing), stride2_alone = stride2.run(nothing);
  // The other layer's whole forward and backward between a layer's forward and its backward.
  EXPECT_TRUE(stride1.run([&] { stride2.run(nothing); }) == stride1_alone);
  EXPECT_TRUE(stride2.run([&] { stride1.run(nothing); }) == stride2_alone);
  // Both on two threads at once, many times over.
  bool same[2] = {true, true};
  std::thread other([&] {
    for (int i = 0; i < 20; ++i) same[1] = same[1] && stride2.run(nothing) == stride2_alone;
  });
  for (int i = 0; i < 20; ++i) same[0] = same[0] && stride1.run(nothing) == stride1_alone;
  other.join();
  EXPECT_TRUE(same[0]);
  EXPECT_TRUE(same[1]);
}

}  // namespace
}  // namespace corrmp::nn
