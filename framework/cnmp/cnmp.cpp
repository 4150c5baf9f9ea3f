// The CNMP forward and backward passes, prediction and model files.
#include "cnmp/cnmp.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace corrmp {

namespace {

std::vector<nn::Index> encoder_sizes(const CnmpArchitecture& a) {
  std::vector<nn::Index> sizes{a.d_x + a.d_y};
  for (int i = 0; i < a.encoder_layers; ++i) sizes.push_back(a.width);
  return sizes;
}

std::vector<nn::Index> decoder_sizes(const CnmpArchitecture& a) {
  std::vector<nn::Index> sizes{a.width + a.d_context + a.d_x};
  for (int i = 1; i < a.decoder_layers; ++i) sizes.push_back(a.width);
  sizes.push_back(2 * a.d_y);
  return sizes;
}

}  // namespace

template <class S>
Cnmp<S>::Cnmp(const CnmpArchitecture& architecture, nn::Rng& rng)
    : architecture_(architecture),
      encoder_(encoder_sizes(architecture), rng),
      decoder_(decoder_sizes(architecture), rng),
      loss_(architecture.min_std) {}

template <class S>
void Cnmp<S>::fill_decoder_input(nn::MatRef<S> input, nn::ConstMatRef<S> contexts,
                                 nn::ConstMatRef<S> target_x,
                                 const std::vector<int>& target_counts) const {
  const auto& a = architecture_;
  nn::Index target_row = 0;
  for (size_t b = 0; b < target_counts.size(); ++b) {
    const int m = target_counts[b];
    if (a.d_context > 0) {
      input.block(target_row, a.width, m, a.d_context).rowwise() = contexts.row(b);
    }
    target_row += m;
  }
  input.rightCols(a.d_x) = target_x;
}

template <class S>
void Cnmp<S>::average_encodings(nn::MatRef<S> input, const std::vector<int>& observation_counts,
                                const std::vector<int>& target_counts) {
  const auto& a = architecture_;
  const auto encoded = encoder_.output();
  auto r = representation_.view();
  nn::Index obs_row = 0, target_row = 0;
  for (size_t b = 0; b < observation_counts.size(); ++b) {
    const int n = observation_counts[b], m = target_counts[b];
    const auto task = static_cast<nn::Index>(b);
    r.row(task) = encoded.middleRows(obs_row, n).colwise().sum() / static_cast<S>(n);
    input.block(target_row, 0, m, a.width).rowwise() = r.row(task);
    obs_row += n;
    target_row += m;
  }
}

template <class S>
void Cnmp<S>::spread_representation_grad(nn::ConstMatRef<S> d_input,
                                         const CnmpBatchCounts& counts) {
  auto d_encoded = d_encoded_.view();
  nn::Index obs_row = 0, target_row = 0;
  for (size_t b = 0; b < counts.observations.size(); ++b) {
    const int n = counts.observations[b], m = counts.targets[b];
    // r_b is the mean of n encodings: each receives 1/n of dL/dr_b.
    d_encoded.middleRows(obs_row, n).rowwise() =
        d_input.block(target_row, 0, m, architecture_.width).colwise().sum() / static_cast<S>(n);
    obs_row += n;
    target_row += m;
  }
}

template <class S>
void Cnmp<S>::forward(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
                      nn::ConstMatRef<S> target_x, const std::vector<int>& observation_counts,
                      const std::vector<int>& target_counts) {
  const auto& a = architecture_;
  encoder_.forward(observations);
  representation_.resize(static_cast<nn::Index>(observation_counts.size()), a.width);
  auto input = decoder_input_.resize(target_x.rows(), a.width + a.d_context + a.d_x);
  fill_decoder_input(input, contexts, target_x, target_counts);
  average_encodings(input, observation_counts, target_counts);
  decoder_.forward(input);
}

template <class S>
S Cnmp<S>::train_step(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
                      nn::ConstMatRef<S> target_x, nn::ConstMatRef<S> target_y,
                      const CnmpBatchCounts& counts) {
  const auto& a = architecture_;
  forward(observations, contexts, target_x, counts.observations, counts.targets);
  const auto output = decoder_.output();
  auto d_output = d_output_.resize(output.rows(), output.cols());
  const S loss = loss_.value_and_grad(output.leftCols(a.d_y), output.rightCols(a.d_y), target_y,
                                      d_output.leftCols(a.d_y), d_output.rightCols(a.d_y));
  const auto d_input = decoder_.backward(d_output);
  d_encoded_.resize(observations.rows(), a.width);
  spread_representation_grad(d_input, counts);
  encoder_.backward_params_only(d_encoded_.view());
  return loss;
}

template <class S>
void Cnmp<S>::prepare_step(nn::ConstMatRef<S> observations, nn::ConstMatRef<S> contexts,
                           nn::ConstMatRef<S> target_x, const CnmpBatchCounts& counts) {
  const auto& a = architecture_;
  encoder_.prepare(observations.rows());
  encoder_.input() = observations;
  decoder_.prepare(target_x.rows());
  fill_decoder_input(decoder_.input(), contexts, target_x, counts.targets);
  representation_.resize(static_cast<nn::Index>(counts.observations.size()), a.width);
  d_output_.resize(target_x.rows(), 2 * a.d_y);
  d_encoded_.resize(observations.rows(), a.width);
}

template <class S>
S Cnmp<S>::train_step_part(nn::ConstMatRef<S> target_y, const CnmpBatchCounts& counts,
                           const nn::Team& team) {
  const auto& a = architecture_;
  encoder_.forward_part(team);
  // The column sums over observations and targets run on member 0 alone, as whole-width Eigen
  // expressions on the buffers train_step uses: Eigen's summation order depends on where a block
  // starts in memory, so cutting them would change the last bits.
  if (team.member == 0) average_encodings(decoder_.input(), counts.observations, counts.targets);
  team.sync();
  decoder_.forward_part(team);
  if (team.member == 0) {
    const auto output = decoder_.output();
    auto d_output = d_output_.view();
    shared_loss_ = loss_.value_and_grad(output.leftCols(a.d_y), output.rightCols(a.d_y), target_y,
                                        d_output.leftCols(a.d_y), d_output.rightCols(a.d_y));
  }
  team.sync();
  const auto d_input = decoder_.backward_part(d_output_.view(), true, team);
  if (team.member == 0) spread_representation_grad(d_input, counts);
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
  const std::vector<int> observation_counts{static_cast<int>(observations.rows())};
  const std::vector<int> target_counts{static_cast<int>(query_x.rows())};
  forward(observations, context, query_x, observation_counts, target_counts);
  const auto output = decoder_.output();
  mean = output.leftCols(a.d_y);
  std.resize(output.rows(), a.d_y);
  loss_.std_from_raw(output.rightCols(a.d_y), std);
}

template <class S>
std::vector<nn::Parameter<S>> Cnmp<S>::parameters() {
  auto params = encoder_.parameters("encoder.");
  nn::append_parameters(params, decoder_.parameters("decoder."));
  return params;
}

template <class S>
int64_t Cnmp<S>::parameter_count() const {
  return encoder_.num_parameters() + decoder_.num_parameters();
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
