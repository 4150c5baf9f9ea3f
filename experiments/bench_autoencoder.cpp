// bench_autoencoder: training speed of the context autoencoder (Google Benchmark) with the
// paper's architecture (Section III "Learning the Context": 64x64 RGB images, kernel 3, strides
// [2, 1, 2, 1, 2], filters [32, 32, 64, 64, 64], latent 8, Adam 3e-4). One iteration is one
// minibatch step: forward + backward on every image + gradient reduction + Adam step, with the
// data-parallel trainer on 1 or 2 threads (context/autoencoder/data_parallel_trainer.hpp).
// items_per_second is images per second; GFLOP/s counts the multiply-adds of the convolution
// and Linear products (2 flops each) as direct convolutions compute them: forward, weight
// gradient and input gradient. The stride-1 layers run Winograd's algorithm
// (nn/winograd_conv3x3.hpp) with fewer multiply-adds, so this is an effective rate.
// Arguments: {batch size, threads}.
// BM_conv_product compares the two implementations of nn/gemm.hpp on four of the training
// step's product shapes (which the kernel there was chosen by): Eigen (argument 0) and the
// AVX-512 kernel (argument 1, Eigen again in builds without AVX-512).
#include <benchmark/benchmark.h>

#include <numeric>
#include <string>
#include <vector>

#include "context/autoencoder/data_parallel_trainer.hpp"
#include "nn/gemm.hpp"

namespace corrmp {
namespace {

// Multiply-adds of one forward pass over one image.
double forward_macs(const AutoencoderArchitecture& a) {
  const std::vector<int> sizes = a.encoder_sizes();
  double macs = 0.0;
  int channels = a.channels;
  for (size_t i = 0; i < sizes.size(); ++i) {
    // conv i and its mirror have the same product sizes.
    macs += 2.0 * sizes[i] * sizes[i] * a.filters[i] * channels * a.kernel_size * a.kernel_size;
    channels = a.filters[i];
  }
  const double flat = static_cast<double>(a.filters.back()) * sizes.back() * sizes.back();
  return macs + 2.0 * flat * a.latent_size;
}

void BM_train_step(benchmark::State& state) {
  const auto batch = static_cast<nn::Index>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const AutoencoderArchitecture a;  // the paper's
  nn::Rng init(1);
  ConvAutoencoder<float> model(a, init);
  nn::Mat<float> data(batch, model.image_values());
  for (nn::Index i = 0; i < data.size(); ++i) data.data()[i] = static_cast<float>(i % 251) / 250.0f;
  std::vector<int> order(static_cast<size_t>(batch));
  std::iota(order.begin(), order.end(), 0);
  DataParallelTrainer trainer(model, threads, 3e-4);
  trainer.step(data, order.data(), batch);  // warm-up: buffers sized
  for (auto _ : state) benchmark::DoNotOptimize(trainer.step(data, order.data(), batch));
  const double images = static_cast<double>(state.iterations()) * static_cast<double>(batch);
  state.SetItemsProcessed(static_cast<int64_t>(images));
  // Backward: weight gradient and input gradient, each as costly as the forward product.
  state.counters["GFLOP/s"] =
      benchmark::Counter(3.0 * 2.0 * forward_macs(a) * images / 1e9, benchmark::Counter::kIsRate);
  state.counters["params"] = static_cast<double>(model.parameter_count());
}

BENCHMARK(BM_train_step)
    ->Args({16, 1})
    ->Args({16, 2})
    ->Args({32, 1})
    ->Args({32, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// C (m x n) (+)= op(A) op(B) with k terms, as a 16-image shard of the paper's architecture runs it
// (a Winograd term's product on one 32x32 image: 64 tiles).
struct ProductShape {
  const char* name;
  nn::Index m, n, k;
  nn::Op op_a, op_b;
  bool accumulate;
};
const ProductShape kProductShapes[] = {
    {"winograd32_forward", 32, 64, 32, nn::Op::kPlain, nn::Op::kPlain, false},
    {"winograd32_weight_grad", 32, 32, 64, nn::Op::kPlain, nn::Op::kTransposed, true},
    {"conv2_weight_grad", 64, 288, 128, nn::Op::kPlain, nn::Op::kTransposed, true},
    {"deconv2_forward", 288, 128, 64, nn::Op::kTransposed, nn::Op::kPlain, false},
};

void BM_conv_product(benchmark::State& state) {
  const ProductShape& s = kProductShapes[state.range(0)];
  const bool ours = state.range(1) == 1;
  const nn::Mat<float> a = s.op_a == nn::Op::kPlain ? nn::Mat<float>::Random(s.m, s.k)
                                                    : nn::Mat<float>::Random(s.k, s.m);
  const nn::Mat<float> b = s.op_b == nn::Op::kPlain ? nn::Mat<float>::Random(s.k, s.n)
                                                    : nn::Mat<float>::Random(s.n, s.k);
  nn::Mat<float> c = nn::Mat<float>::Zero(s.m, s.n);
  nn::Buffer<float> scratch;
  const auto eigen = [&](const auto& x, const auto& y) {
    if (s.accumulate)
      c.noalias() += x * y;
    else
      c.noalias() = x * y;
  };
  for (auto _ : state) {
    if (ours)
      nn::gemm<float>(a, s.op_a, b, s.op_b, c, s.accumulate, scratch);
    else if (s.op_a == nn::Op::kTransposed)
      eigen(a.transpose(), b);
    else if (s.op_b == nn::Op::kTransposed)
      eigen(a, b.transpose());
    else
      eigen(a, b);
    benchmark::DoNotOptimize(c.data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(std::string(s.name) + (ours ? " nn::gemm" : " Eigen"));
  state.counters["GFLOP/s"] = benchmark::Counter(
      2.0 * static_cast<double>(s.m * s.n * s.k) * static_cast<double>(state.iterations()) / 1e9,
      benchmark::Counter::kIsRate);
}

BENCHMARK(BM_conv_product)->ArgsProduct({{0, 1, 2, 3}, {0, 1}});

}  // namespace
}  // namespace corrmp

BENCHMARK_MAIN();
