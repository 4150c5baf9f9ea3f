// The CNMP forward and backward passes, prediction and model files.
#include "cnmp/cnmp.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "nn/activation.hpp"
#include "nn/relu_fusion.hpp"

namespace corrmp {

namespace {

std::vector<nn::Index> encoder_sizes(const CnmpArchitecture& a) {
  std::vector<nn::Index> sizes{a.d_x + a.d_y};
  for (int i = 0; i < a.encoder_layers; ++i) sizes.push_back(a.width);
  return sizes;
}

// The decoder's first layer's outputs.
nn::Index first_layer_outputs(const CnmpArchitecture& a) {
  return a.decoder_layers > 1 ? a.width : 2 * a.d_y;
}

// The decoder's layers after the first (width -> ... -> 2 d_y), drawn from rng after it.
template <class S>
std::optional<nn::Mlp<S>> decoder_rest(const CnmpArchitecture& a, nn::Rng& rng) {
  if (a.decoder_layers < 2) return std::nullopt;
  std::vector<nn::Index> sizes{a.width};
  for (int i = 2; i < a.decoder_layers; ++i) sizes.push_back(a.width);
  sizes.push_back(2 * a.d_y);
  return nn::Mlp<S>(sizes, rng);
}

}  // namespace

template <class S>
Cnmp<S>::Cnmp(const CnmpArchitecture& architecture, nn::Rng& rng)
    : architecture_(architecture),
      encoder_(encoder_sizes(architecture), rng),
      decoder_first_(architecture.width, architecture.d_context + architecture.d_x,
                     first_layer_outputs(architecture), rng),
      decoder_rest_(decoder_rest<S>(architecture, rng)),
      loss_(architecture.min_std) {}

template <class S>
nn::MatMap<S> Cnmp<S>::first_layer_output() {
  return decoder_rest_ ? decoder_rest_->input() : one_layer_output_.view();
}

template <class S>
nn::ConstMatMap<S> Cnmp<S>::output() const {
  return decoder_rest_ ? decoder_rest_->output() : one_layer_output_.view();
}

template <class S>
void Cnmp<S>::fill_queries(nn::ConstMatRef<S> contexts, nn::ConstMatRef<S> target_x,
                           const std::vector<int>& target_counts) {
  const auto& a = architecture_;
  auto queries = queries_.resize(target_x.rows(), a.d_context + a.d_x);
  nn::Index target_row = 0;
  for (size_t b = 0; b < target_counts.size(); ++b) {
    const int m = target_counts[b];
    if (a.d_context > 0) queries.block(target_row, 0, m, a.d_context).rowwise() = contexts.row(b);
    target_row += m;
  }
  queries.rightCols(a.d_x) = target_x;
}

template <class S>
void Cnmp<S>::average_encodings(const std::vector<int>& observation_counts) {
  const auto encoded = encoder_.output();
  auto r = representation_.view();
  nn::Index obs_row = 0;
  for (size_t b = 0; b < observation_counts.size(); ++b) {
    const int n = observation_counts[b];
    r.row(static_cast<nn::Index>(b)) =
        encoded.middleRows(obs_row, n).colwise().sum() / static_cast<S>(n);
    obs_row += n;
  }
}

template <class S>
void Cnmp<S>::spread_representation_grad(const CnmpBatchCounts& counts, nn::Index first,
                                         nn::Index count) {
  if (count == 0) return;
  const auto d_r = std::as_const(d_representation_).view().middleCols(first, count);
  auto d_encoded = d_encoded_.view().middleCols(first, count);
  nn::Index obs_row = 0;
  for (size_t b = 0; b < counts.observations.size(); ++b) {
    const int n = counts.observations[b];
    // r_b is the mean of n encodings: each receives 1/n of dL/dr_b (row by row: Eigen would
    // evaluate the quotient into a heap temporary for a rowwise assignment).
    for (int i = 0; i < n; ++i, ++obs_row)
      d_encoded.row(obs_row) = d_r.row(static_cast<nn::Index>(b)) / static_cast<S>(n);
  }
}

template <class S>
void Cnmp<S>::prepare_forward(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
                              nn::ConstMatRef<S> target_x, const CnmpBatchCounts& counts) {
  const auto& a = architecture_;
  const auto tasks = static_cast<nn::Index>(counts.observations.size());
  const auto total = [](const std::vector<int>& v) {
    return std::accumulate(v.begin(), v.end(), nn::Index(0));
  };
  const auto at_least = [](const std::vector<int>& v, int least) {
    return std::all_of(v.begin(), v.end(), [least](int n) { return n >= least; });
  };
  if (observations.cols() != a.d_x + a.d_y || target_x.cols() != a.d_x ||
      contexts.cols() != a.d_context || (a.d_context > 0 && contexts.rows() != tasks) ||
      counts.targets.size() != counts.observations.size() || !at_least(counts.observations, 1) ||
      !at_least(counts.targets, 0) || total(counts.observations) != observations.rows() ||
      total(counts.targets) != target_x.rows())
    throw std::invalid_argument(fmt::format(
        "CNMP batch of {} tasks: observations {}x{}, contexts {}x{}, queries {}x{} and {} target "
        "counts do not match the network (d_x {}, d_y {}, context {}) or the counts (at least one "
        "observation per task)",
        tasks, observations.rows(), observations.cols(), contexts.rows(), contexts.cols(),
        target_x.rows(), target_x.cols(), counts.targets.size(), a.d_x, a.d_y, a.d_context));
  encoder_.prepare(observations.rows());
  encoder_.input() = observations;
  representation_.resize(tasks, a.width);
  fill_queries(contexts, target_x, counts.targets);
  decoder_first_.prepare(tasks);
  if (decoder_rest_)
    decoder_rest_->prepare(target_x.rows());
  else
    one_layer_output_.resize(target_x.rows(), 2 * a.d_y);
}

template <class S>
void Cnmp<S>::forward_part(const CnmpBatchCounts& counts, const nn::Team& team) {
  encoder_.forward_part(team);
  // The column sums over observations run on member 0 alone, as whole-width Eigen expressions:
  // Eigen's summation order depends on where a block starts in memory, so cutting them would
  // change the last bits.
  if (team.member == 0) average_encodings(counts.observations);
  team.sync();
  const auto [first, count] = team.share(decoder_first_.out_features());
  auto z = first_layer_output();
  decoder_first_.forward_part(representation_.view(), queries_.view(), counts.targets, z, first,
                              count);
  if (decoder_rest_ && count > 0) nn::relu_in_place(z.middleCols(first, count));
  team.sync();
  if (decoder_rest_) decoder_rest_->forward_part(team);
}

template <class S>
S Cnmp<S>::train_step(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
                      nn::ConstMatRef<S> target_x, nn::ConstMatRef<S> target_y,
                      const CnmpBatchCounts& counts) {
  prepare_step(observations, contexts, target_x, counts);
  return train_step_part(target_y, counts, nn::Team{});
}

template <class S>
void Cnmp<S>::prepare_step(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
                           nn::ConstMatRef<S> target_x, const CnmpBatchCounts& counts) {
  const auto& a = architecture_;
  prepare_forward(observations, contexts, target_x, counts);
  d_output_.resize(target_x.rows(), 2 * a.d_y);
  d_first_.resize(target_x.rows(), decoder_first_.out_features());
  d_representation_.resize(static_cast<nn::Index>(counts.observations.size()), a.width);
  d_encoded_.resize(observations.rows(), a.width);
}

template <class S>
S Cnmp<S>::train_step_part(nn::ConstMatRef<S> target_y, const CnmpBatchCounts& counts,
                           const nn::Team& team) {
  const auto& a = architecture_;
  forward_part(counts, team);
  if (team.member == 0) {
    const auto out = output();
    auto d_output = d_output_.view();
    shared_loss_ = loss_.value_and_grad(out.leftCols(a.d_y), out.rightCols(a.d_y), target_y,
                                        d_output.leftCols(a.d_y), d_output.rightCols(a.d_y));
  }
  team.sync();
  // g = dL/dz of the first layer: the decoder's output gradient, or the gradient the other
  // layers pass back through the first layer's ReLU.
  const auto [first, count] = team.share(decoder_first_.out_features());
  if (decoder_rest_) {
    const auto d_input = decoder_rest_->backward_part(d_output_.view(), true, team);
    const auto activation = decoder_rest_->input();  // relu(z)
    if (count > 0)
      nn::Relu<S>().backward(activation.middleCols(first, count), d_input.middleCols(first, count),
                             d_first_.view().middleCols(first, count));
  }
  const nn::ConstMatMap<S> g =
      decoder_rest_ ? std::as_const(d_first_).view() : std::as_const(d_output_).view();
  decoder_first_.backward_params_part(representation_.view(), queries_.view(), g, counts.targets,
                                      first, count);
  team.sync();
  const auto [r_first, r_count] = team.share(a.width);
  decoder_first_.representation_grad_part(d_representation_.view(), r_first, r_count);
  spread_representation_grad(counts, r_first, r_count);
  team.sync();
  encoder_.backward_part(d_encoded_.view(), false, team);
  return shared_loss_;
}

template <class S>
void Cnmp<S>::predict(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> context,
                      nn::ConstMatRef<S> query_x, Mat& mean, Mat& std) {
  const auto& a = architecture_;
  if (observations.rows() < 1 || observations.cols() != a.d_x + a.d_y) {
    throw std::invalid_argument(fmt::format(
        "CNMP prediction needs at least one observation of {} values (x then y), got {}x{}",
        a.d_x + a.d_y, observations.rows(), observations.cols()));
  }
  if (context.cols() != a.d_context || (a.d_context > 0 && context.rows() != 1)) {
    throw std::invalid_argument(fmt::format("CNMP prediction needs a context of size {}, got {}",
                                            a.d_context, context.size()));
  }
  if (query_x.cols() != a.d_x) {
    throw std::invalid_argument(
        fmt::format("CNMP queries have {} input values, got {}", a.d_x, query_x.cols()));
  }
  const CnmpBatchCounts counts{{static_cast<int>(observations.rows())},
                               {static_cast<int>(query_x.rows())}};
  prepare_forward(observations, context, query_x, counts);
  forward_part(counts, nn::Team{});
  const auto out = output();
  mean = out.leftCols(a.d_y);
  std.resize(out.rows(), a.d_y);
  loss_.std_from_raw(out.rightCols(a.d_y), std);
}

template <class S>
std::vector<nn::Parameter<S>> Cnmp<S>::parameters() {
  auto params = encoder_.parameters("encoder.");
  nn::append_parameters(params, decoder_first_.parameters("decoder.layers.0."));
  if (decoder_rest_) nn::append_parameters(params, decoder_rest_->parameters("decoder.", 1));
  return params;
}

template <class S>
int64_t Cnmp<S>::parameter_count() const {
  return encoder_.num_parameters() + decoder_first_.num_parameters() +
         (decoder_rest_ ? decoder_rest_->num_parameters() : 0);
}

template <class S>
void Cnmp<S>::save_to(nn::ModelFile& file) {
  const auto& a = architecture_;
  file.hyper["model"] = "cnmp";
  file.set_hyper_int("cnmp.d_x", a.d_x);
  file.set_hyper_int("cnmp.d_y", a.d_y);
  file.set_hyper_int("cnmp.d_context", a.d_context);
  file.set_hyper_int("cnmp.encoder_layers", a.encoder_layers);
  file.set_hyper_int("cnmp.decoder_layers", a.decoder_layers);
  file.set_hyper_int("cnmp.width", a.width);
  file.set_hyper_double("cnmp.min_std", a.min_std);
  file.add_parameters(parameters());
}

template <class S>
CnmpArchitecture Cnmp<S>::architecture_of(const nn::ModelFile& file) {
  CnmpArchitecture a;
  a.d_x = static_cast<int>(file.hyper_int("cnmp.d_x"));
  a.d_y = static_cast<int>(file.hyper_int("cnmp.d_y"));
  a.d_context = static_cast<int>(file.hyper_int("cnmp.d_context"));
  a.encoder_layers = static_cast<int>(file.hyper_int("cnmp.encoder_layers"));
  a.decoder_layers = static_cast<int>(file.hyper_int("cnmp.decoder_layers"));
  a.width = static_cast<int>(file.hyper_int("cnmp.width"));
  a.min_std = file.hyper_double("cnmp.min_std");
  return a;
}

template <class S>
void Cnmp<S>::load_from(const nn::ModelFile& file) {
  const CnmpArchitecture stored = architecture_of(file);
  const auto& a = architecture_;
  if (stored.d_x != a.d_x || stored.d_y != a.d_y || stored.d_context != a.d_context ||
      stored.encoder_layers != a.encoder_layers || stored.decoder_layers != a.decoder_layers ||
      stored.width != a.width) {
    throw nn::ModelFileError(fmt::format(
        "model file '{}': CNMP architecture (d_x {}, d_y {}, context {}, layers {}/{}, width {}) "
        "differs from the expected (d_x {}, d_y {}, context {}, layers {}/{}, width {})",
        file.source, stored.d_x, stored.d_y, stored.d_context, stored.encoder_layers,
        stored.decoder_layers, stored.width, a.d_x, a.d_y, a.d_context, a.encoder_layers,
        a.decoder_layers, a.width));
  }
  file.load_parameters(parameters());
}

template class Cnmp<float>;
template class Cnmp<double>;

}  // namespace corrmp
