// Data-parallel Adam steps for the context autoencoder, so that the paper's training (Section III
// "Learning the Context": Adam, learning rate 3e-4, 70 epochs of 360 images) uses every core.
//
// With T shards, shard 0 is computed on the model itself and shard r > 0 on its own replica (a
// copy of the model with its own weights, activations and gradients). A minibatch of B images
// is cut into contiguous shards [r B / T, (r + 1) B / T); for shard r a worker copies the
// model's weights into the replica, zeroes its gradients and runs
//   g_r = (B_r / B) grad L_r            (L_r: mean squared error of its B_r images)
// Then the replica gradients are added to the model's in the fixed order r = 1, ..., T - 1, so
// g = sum_r g_r is the gradient of the minibatch's mean loss, and one Adam step updates the
// model. This sum and the Adam step run on the workers too, each on its own range of parameter
// entries (blocks of kUpdateBlock entries, on Adam's range boundaries): every entry is summed
// and updated by the same operations whichever worker has it. The shards run on W <= T workers
// (worker_pool.hpp; worker w takes shards w, w + W, ...): results are deterministic for given
// inputs and T, whatever W, so a run keeps its results when a sweep gives it fewer cores.
// Different T compute the same mathematical step but sum per-image gradient contributions in
// another order (and run their matrix products on other sizes), so they agree only up to float
// rounding, which training slowly amplifies. Once every worker has seen its largest shard, a
// step allocates nothing beyond Eigen's GEMM workspace where Eigen computes the products
// (nn/conv2d.hpp). The convolutions' transformed weights (nn/winograd_conv3x3.hpp,
// nn/winograd_stride2_conv3x3.hpp), the same for every shard, are computed once per step on the
// model, the workers sharing the layers, and read by the replicas.
#pragma once

#include <cstdint>
#include <vector>

#include "context/autoencoder/conv_autoencoder.hpp"
#include "core/worker_pool.hpp"
#include "nn/adam.hpp"
#include "nn/buffer.hpp"

namespace corrmp {

class DataParallelTrainer {
 public:
  /// Copies `model` into shards - 1 replicas, computed on `workers` threads (0: one per shard,
  /// at most `shards`); `model` must outlive the trainer and is the one Adam updates.
  DataParallelTrainer(ConvAutoencoder<float>& model, int shards, double learning_rate,
                      int workers = 0);

  /// One Adam step on the rows order[0], ..., order[batch - 1] of `data` (one image per row);
  /// returns the minibatch's mean squared error (before the step).
  double step(nn::ConstMatRef<float> data, const int* order, nn::Index batch);

  /// Mean squared reconstruction error of the model over all rows of `data`.
  double evaluate(nn::ConstMatRef<float> data);

  int shards() const { return shards_; }
  int threads() const { return pool_.size(); }
  std::int64_t steps() const { return adam_.step_count(); }

 private:
  ConvAutoencoder<float>& worker(int r) { return r == 0 ? model_ : replicas_[r - 1]; }
  // Copies the model's weights into replica r (nothing for r = 0); reads the model only.
  void sync_weights(int r);
  // Adds the non-empty shards' gradients to the model's and updates it by Adam (its step begun),
  // on the entries of blocks [first, last).
  void reduce_and_update(size_t first, size_t last, nn::Index batch);

  // The model's transformed weights, each worker its share of the layers, before shards run.
  void transform_weights();

  // Blocks of this many entries: on Adam's range boundaries, so that the update is exactly
  // Adam::step's.
  static constexpr nn::Index kUpdateBlock = 2 * nn::Adam<float>::kRangeAlignment;

  // Runs task(r) for every shard r on the pool's workers.
  template <class Task>
  void for_each_shard(Task&& task) {
    pool_.run([&](int w) {
      for (int r = w; r < shards_; r += pool_.size()) task(r);
    });
  }

  ConvAutoencoder<float>& model_;
  int shards_;
  std::vector<ConvAutoencoder<float>> replicas_;
  WorkerPool pool_;
  std::vector<std::vector<nn::Parameter<float>>> params_;  // [shard][parameter]
  std::vector<nn::Buffer<float>> inputs_;                  // each shard's images
  std::vector<double> partial_;                            // each shard's share of the loss
  nn::Adam<float> adam_;
  std::vector<nn::Adam<float>::Range> blocks_;  // every parameter entry, in parameter order
};

}  // namespace corrmp
