// Data-parallel Adam steps on model replicas (data_parallel_trainer.hpp).
#include "context/autoencoder/data_parallel_trainer.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "nn/denormals.hpp"

namespace corrmp {

DataParallelTrainer::DataParallelTrainer(ConvAutoencoder<float>& model, int shards,
                                         double learning_rate, int workers)
    : model_(model),
      shards_(shards),
      replicas_(static_cast<size_t>(shards > 1 ? shards - 1 : 0), model),
      pool_(workers > 0 ? std::min(workers, shards) : shards),
      inputs_(static_cast<size_t>(shards)),
      partial_(static_cast<size_t>(shards), 0.0),
      adam_(model.parameters(), nn::AdamOptions{learning_rate}),
      blocks_(nn::Adam<float>::ranges(adam_.parameters(), kUpdateBlock)) {
  params_.push_back(model.parameters());
  for (auto& replica : replicas_) {
    params_.push_back(replica.parameters());
    replica.share_weight_transforms(model);
  }
}

void DataParallelTrainer::transform_weights() {
  if (replicas_.empty()) return;  // the model's layers transform their weights when they run
  pool_.run([&](int w) { model_.transform_weights(w, pool_.size()); });
}

void DataParallelTrainer::reduce_and_update(size_t first, size_t last, nn::Index batch) {
  for (size_t b = first; b < last; ++b) {
    const nn::Adam<float>::Range& block = blocks_[b];
    const nn::Index size = block.end - block.begin;
    float* sum = params_[0][block.parameter].grad + block.begin;
    for (int r = 1; r < shards_; ++r) {
      if ((r + 1) * batch / shards_ == r * batch / shards_) continue;  // empty shard
      const float* g = params_[r][block.parameter].grad + block.begin;
      for (nn::Index i = 0; i < size; ++i) sum[i] += g[i];
    }
    adam_.update_range(block.parameter, block.begin, block.end);
  }
}

void DataParallelTrainer::sync_weights(int r) {
  if (r == 0) return;
  for (size_t k = 0; k < params_[0].size(); ++k) params_[r][k].values() = params_[0][k].values();
}

double DataParallelTrainer::step(nn::ConstMatRef<float> data, const int* order, nn::Index batch) {
  if (batch < 1) throw std::invalid_argument("DataParallelTrainer::step: empty minibatch");
  const int threads = shards_;
  transform_weights();
  for_each_shard([&](int r) {
    const nn::ScopedFlushDenormals flush_denormals;
    sync_weights(r);
    nn::zero_grad(params_[r]);
    const nn::Index begin = r * batch / threads, end = (r + 1) * batch / threads;
    partial_[r] = 0.0;
    if (end == begin) return;
    nn::MatMap<float> x = inputs_[r].resize(end - begin, data.cols());
    for (nn::Index k = begin; k < end; ++k) x.row(k - begin) = data.row(order[k]);
    const float share = static_cast<float>(end - begin) / static_cast<float>(batch);
    partial_[r] = static_cast<double>(share) * worker(r).train_step(x, share);
  });
  adam_.begin_step();
  const size_t blocks = blocks_.size(), workers = static_cast<size_t>(pool_.size());
  pool_.run([&](int w) {
    const size_t index = static_cast<size_t>(w);
    reduce_and_update(index * blocks / workers, (index + 1) * blocks / workers, batch);
  });
  return std::accumulate(partial_.begin(), partial_.end(), 0.0);
}

double DataParallelTrainer::evaluate(nn::ConstMatRef<float> data) {
  if (data.rows() == 0) throw std::invalid_argument("DataParallelTrainer::evaluate: no images");
  const int threads = shards_;
  const nn::Index rows = data.rows();
  transform_weights();
  for_each_shard([&](int r) {
    const nn::ScopedFlushDenormals flush_denormals;
    sync_weights(r);
    const nn::Index begin = r * rows / threads, end = (r + 1) * rows / threads;
    partial_[r] = 0.0;
    if (end > begin)
      partial_[r] = worker(r).reconstruction_mse(data.middleRows(begin, end - begin)) *
                    static_cast<double>(end - begin);
  });
  return std::accumulate(partial_.begin(), partial_.end(), 0.0) / static_cast<double>(rows);
}

}  // namespace corrmp
