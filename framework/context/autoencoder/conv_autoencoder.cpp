// The convolutional autoencoder (formulas in conv_autoencoder.hpp).
#include "context/autoencoder/conv_autoencoder.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "nn/activation.hpp"
#include "nn/check.hpp"
#include "nn/mse_loss.hpp"

namespace corrmp {
namespace {

constexpr const char* kModelName = "conv_autoencoder";

const AutoencoderArchitecture& validated(const AutoencoderArchitecture& a) {
  a.validate();
  return a;
}

template <class S>
std::vector<nn::Conv2d<S>> build_encoder(const AutoencoderArchitecture& a, nn::Rng& rng) {
  const std::vector<int> sizes = a.encoder_sizes();
  std::vector<nn::Conv2d<S>> convs;
  convs.reserve(sizes.size());
  int channels = a.channels, size = a.image_size;
  for (size_t i = 0; i < sizes.size(); ++i) {
    nn::Conv2dOptions o;
    o.in_channels = channels;
    o.out_channels = a.filters[i];
    o.kernel_size = a.kernel_size;
    o.stride = a.strides[i];
    o.padding = a.padding();
    convs.emplace_back(o, size, size, rng);
    channels = a.filters[i];
    size = sizes[i];
  }
  return convs;
}

// Index i mirrors encoder convolution i; built (and initialised) deepest first, the order in
// which they run.
template <class S>
std::vector<nn::ConvTranspose2d<S>> build_decoder(const AutoencoderArchitecture& a, nn::Rng& rng) {
  const std::vector<int> sizes = a.encoder_sizes();
  std::vector<nn::ConvTranspose2d<S>> deconvs;
  deconvs.reserve(sizes.size());
  for (size_t i = sizes.size(); i-- > 0;) {
    const int in_size = sizes[i];
    const int out_size = i == 0 ? a.image_size : sizes[i - 1];
    nn::ConvTranspose2dOptions o;
    o.in_channels = a.filters[i];
    o.out_channels = i == 0 ? a.channels : a.filters[i - 1];
    o.kernel_size = a.kernel_size;
    o.stride = a.strides[i];
    o.padding = a.padding();
    o.output_padding = out_size - ((in_size - 1) * a.strides[i] - 2 * a.padding() + a.kernel_size);
    deconvs.emplace_back(o, in_size, in_size, rng);
  }
  std::reverse(deconvs.begin(), deconvs.end());
  return deconvs;
}

// Encoder output entries: filters.back() x H_L x H_L.
nn::Index flat_size(const AutoencoderArchitecture& a) {
  const nn::Index side = a.encoder_sizes().back();
  return a.filters.back() * side * side;
}

std::vector<int> parse_int_list(const nn::ModelFile& file, const std::string& key) {
  std::vector<int> values;
  std::stringstream text(file.hyper_string(key));
  std::string item;
  while (std::getline(text, item, ',')) {
    try {
      size_t used = 0;
      values.push_back(std::stoi(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw std::runtime_error(fmt::format("model file '{}': hyper '{}' = '{}' is not a list",
                                           file.source, key, file.hyper_string(key)));
    }
  }
  return values;
}

}  // namespace

template <class S>
ConvAutoencoder<S>::ConvAutoencoder(const AutoencoderArchitecture& architecture, nn::Rng& rng)
    : architecture_(validated(architecture)),
      encoder_convs_(build_encoder<S>(architecture_, rng)),
      encoder_fc_(flat_size(architecture_), architecture_.latent_size, rng),
      decoder_fc_(architecture_.latent_size, flat_size(architecture_), rng),
      decoder_convs_(build_decoder<S>(architecture_, rng)),
      encoded_(architecture_.strides.size()),
      decoded_(architecture_.strides.size()) {}

template <class S>
nn::ImageShape ConvAutoencoder<S>::image_shape() const {
  return {architecture_.channels, architecture_.image_size, architecture_.image_size};
}

template <class S>
std::int64_t ConvAutoencoder<S>::parameter_count() const {
  std::int64_t n = encoder_fc_.num_parameters() + decoder_fc_.num_parameters();
  for (const auto& c : encoder_convs_) n += c.num_parameters();
  for (const auto& c : decoder_convs_) n += c.num_parameters();
  return n;
}

template <class S>
std::vector<nn::Parameter<S>> ConvAutoencoder<S>::parameters() {
  std::vector<nn::Parameter<S>> params;
  for (size_t i = 0; i < encoder_convs_.size(); ++i)
    nn::append_parameters(params, encoder_convs_[i].parameters(fmt::format("encoder.conv{}.", i)));
  nn::append_parameters(params, encoder_fc_.parameters("encoder.fc."));
  nn::append_parameters(params, decoder_fc_.parameters("decoder.fc."));
  for (size_t j = decoder_convs_.size(); j-- > 0;)
    nn::append_parameters(params,
                          decoder_convs_[j].parameters(fmt::format("decoder.deconv{}.", j)));
  return params;
}

template <class S>
void ConvAutoencoder<S>::transform_weights(int part, int parts) {
  const size_t layers = encoder_convs_.size();
  for (size_t i = static_cast<size_t>(part); i < 2 * layers; i += static_cast<size_t>(parts)) {
    if (i < layers)
      encoder_convs_[i].transform_weights();
    else
      decoder_convs_[i - layers].transform_weights();
  }
}

template <class S>
void ConvAutoencoder<S>::share_weight_transforms(const ConvAutoencoder& source) {
  for (size_t i = 0; i < encoder_convs_.size(); ++i) {
    encoder_convs_[i].share_weight_transforms(source.encoder_convs_[i]);
    decoder_convs_[i].share_weight_transforms(source.decoder_convs_[i]);
  }
}

template <class S>
nn::MatMap<S> ConvAutoencoder<S>::next_gradient(nn::Index rows, nn::Index cols) {
  nn::MatMap<S> view = gradients_[next_gradient_].resize(rows, cols);
  next_gradient_ = 1 - next_gradient_;
  return view;
}

template <class S>
void ConvAutoencoder<S>::forward_encoder(nn::ConstMatRef<S> x) {
  nn::check_shape("ConvAutoencoder", "images", x, x.rows(), image_values());
  const nn::Index n = x.rows();
  for (size_t i = 0; i < encoder_convs_.size(); ++i) {
    nn::Conv2d<S>& conv = encoder_convs_[i];
    nn::MatMap<S> y = encoded_[i].resize(n, conv.output_shape().size());
    if (i == 0)
      conv.forward(x, y, /*relu=*/true);
    else
      conv.forward(encoded_[i - 1].view(), y, /*relu=*/true);
  }
  encoder_fc_.forward(encoded_.back().view(), latent_.resize(n, architecture_.latent_size));
}

template <class S>
void ConvAutoencoder<S>::forward_decoder(nn::ConstMatRef<S> z) {
  nn::check_shape("ConvAutoencoder", "latents", z, z.rows(), architecture_.latent_size);
  const nn::Index n = z.rows();
  const nn::Relu<S> relu;
  nn::MatMap<S> d = decoder_fc_out_.resize(n, decoder_fc_.out_features());
  decoder_fc_.forward(z, d);
  relu.forward(d, d);
  for (size_t j = decoder_convs_.size(); j-- > 0;) {
    nn::ConvTranspose2d<S>& deconv = decoder_convs_[j];
    nn::MatMap<S> y = decoded_[j].resize(n, deconv.output_shape().size());
    const auto input =
        j + 1 == decoder_convs_.size() ? decoder_fc_out_.view() : decoded_[j + 1].view();
    deconv.forward(input, y, /*relu=*/j > 0);
    if (j == 0) nn::Sigmoid<S>().forward(y, y);
  }
}

template <class S>
S ConvAutoencoder<S>::train_step(nn::ConstMatRef<S> images, S gradient_scale) {
  forward_encoder(images);
  forward_decoder(latent_.view());
  const nn::Index n = images.rows();
  const nn::Relu<S> relu;

  // Loss and its gradient through the output sigmoid. `grad` always views dL/d(output of the
  // layer about to run backward); it lives in one of the two gradient buffers.
  const auto reconstruction = decoded_.front().view();
  const S loss = nn::MseLoss<S>().value(reconstruction, images);
  nn::MatMap<S> output_grad = next_gradient(n, images.cols());
  output_grad = (gradient_scale * static_cast<S>(2.0 / static_cast<double>(images.size()))) *
                (reconstruction - images);
  nn::Sigmoid<S>().backward(reconstruction, output_grad, output_grad);
  S* grad = output_grad.data();
  nn::Index grad_cols = output_grad.cols();
  auto grad_view = [&] { return nn::ConstMatMap<S>(grad, n, grad_cols); };

  // Decoder, from the output back to the latent.
  const size_t layers = decoder_convs_.size();
  for (size_t j = 0; j < layers; ++j) {
    const auto input = j + 1 == layers ? decoder_fc_out_.view() : decoded_[j + 1].view();
    nn::MatMap<S> d_input = next_gradient(n, input.cols());
    decoder_convs_[j].backward(input, grad_view(), d_input, /*relu_input=*/true);
    grad = d_input.data();
    grad_cols = d_input.cols();
  }
  nn::MatMap<S> d_latent = next_gradient(n, architecture_.latent_size);
  decoder_fc_.backward(latent_.view(), grad_view(), d_latent);

  // Encoder, from the latent back to the first convolution.
  nn::MatMap<S> d_flat = next_gradient(n, encoder_fc_.in_features());
  encoder_fc_.backward(encoded_.back().view(), d_latent, d_flat);
  relu.backward(encoded_.back().view(), d_flat, d_flat);
  grad = d_flat.data();
  grad_cols = d_flat.cols();
  for (size_t i = layers; i-- > 1;) {
    const auto input = encoded_[i - 1].view();
    nn::MatMap<S> d_input = next_gradient(n, input.cols());
    encoder_convs_[i].backward(input, grad_view(), d_input, /*relu_input=*/true);
    grad = d_input.data();
    grad_cols = d_input.cols();
  }
  encoder_convs_.front().accumulate_param_grad(images, grad_view());
  return loss;
}

template <class S>
void ConvAutoencoder<S>::encode(nn::ConstMatRef<S> images, nn::MatRef<S> latents) {
  nn::check_shape("ConvAutoencoder::encode", "latents", latents, images.rows(),
                  architecture_.latent_size);
  for (nn::Index begin = 0; begin < images.rows(); begin += kInferenceChunk) {
    const nn::Index rows = std::min(kInferenceChunk, images.rows() - begin);
    forward_encoder(images.middleRows(begin, rows));
    latents.middleRows(begin, rows) = latent_.view();
  }
}

template <class S>
typename ConvAutoencoder<S>::Mat ConvAutoencoder<S>::encode(nn::ConstMatRef<S> images) {
  Mat latents(images.rows(), architecture_.latent_size);
  encode(images, latents);
  return latents;
}

template <class S>
void ConvAutoencoder<S>::decode(nn::ConstMatRef<S> latents, nn::MatRef<S> images) {
  nn::check_shape("ConvAutoencoder::decode", "images", images, latents.rows(), image_values());
  for (nn::Index begin = 0; begin < latents.rows(); begin += kInferenceChunk) {
    const nn::Index rows = std::min(kInferenceChunk, latents.rows() - begin);
    forward_decoder(latents.middleRows(begin, rows));
    images.middleRows(begin, rows) = decoded_.front().view();
  }
}

template <class S>
typename ConvAutoencoder<S>::Mat ConvAutoencoder<S>::decode(nn::ConstMatRef<S> latents) {
  Mat images(latents.rows(), image_values());
  decode(latents, images);
  return images;
}

template <class S>
typename ConvAutoencoder<S>::Mat ConvAutoencoder<S>::reconstruct(nn::ConstMatRef<S> images) {
  Mat out(images.rows(), image_values());
  for (nn::Index begin = 0; begin < images.rows(); begin += kInferenceChunk) {
    const nn::Index rows = std::min(kInferenceChunk, images.rows() - begin);
    forward_encoder(images.middleRows(begin, rows));
    forward_decoder(latent_.view());
    out.middleRows(begin, rows) = decoded_.front().view();
  }
  return out;
}

template <class S>
double ConvAutoencoder<S>::reconstruction_mse(nn::ConstMatRef<S> images) {
  if (images.rows() == 0) throw std::invalid_argument("ConvAutoencoder: no images to evaluate");
  double sum = 0.0;
  for (nn::Index begin = 0; begin < images.rows(); begin += kInferenceChunk) {
    const nn::Index rows = std::min(kInferenceChunk, images.rows() - begin);
    forward_encoder(images.middleRows(begin, rows));
    forward_decoder(latent_.view());
    const auto reconstruction = decoded_.front().view();
    for (nn::Index r = 0; r < rows; ++r)
      sum += (reconstruction.row(r) - images.row(begin + r)).template cast<double>().squaredNorm();
  }
  return sum / static_cast<double>(images.size());
}

template <class S>
void ConvAutoencoder<S>::save_to(nn::ModelFile& file) {
  const auto& a = architecture_;
  file.hyper["model"] = kModelName;
  file.set_hyper_int("autoencoder.image_size", a.image_size);
  file.set_hyper_int("autoencoder.channels", a.channels);
  file.hyper["autoencoder.strides"] = fmt::format("{}", fmt::join(a.strides, ","));
  file.hyper["autoencoder.filters"] = fmt::format("{}", fmt::join(a.filters, ","));
  file.set_hyper_int("autoencoder.kernel_size", a.kernel_size);
  file.set_hyper_int("autoencoder.latent_size", a.latent_size);
  file.add_parameters(parameters());
}

template <class S>
AutoencoderArchitecture ConvAutoencoder<S>::architecture_of(const nn::ModelFile& file) {
  const auto model = file.hyper.find("model");
  if (model == file.hyper.end() || model->second != kModelName) {
    throw std::runtime_error(
        fmt::format("model file '{}': holds model '{}', expected '{}'", file.source,
                    model == file.hyper.end() ? "" : model->second, kModelName));
  }
  AutoencoderArchitecture a;
  a.image_size = static_cast<int>(file.hyper_int("autoencoder.image_size"));
  a.channels = static_cast<int>(file.hyper_int("autoencoder.channels"));
  a.strides = parse_int_list(file, "autoencoder.strides");
  a.filters = parse_int_list(file, "autoencoder.filters");
  a.kernel_size = static_cast<int>(file.hyper_int("autoencoder.kernel_size"));
  a.latent_size = static_cast<int>(file.hyper_int("autoencoder.latent_size"));
  return a;
}

template <class S>
void ConvAutoencoder<S>::load_from(const nn::ModelFile& file) {
  const AutoencoderArchitecture stored = architecture_of(file);
  if (stored != architecture_) {
    throw std::runtime_error(
        fmt::format("model file '{}': autoencoder architecture ({}) differs from the expected ({})",
                    file.source, stored.summary(), architecture_.summary()));
  }
  file.load_parameters(parameters());
}

ConvAutoencoder<float> load_autoencoder(const std::string& path) {
  const nn::ModelFile file = nn::ModelFile::read(path);
  const AutoencoderArchitecture a = ConvAutoencoder<float>::architecture_of(file);
  try {
    a.validate();
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(fmt::format("model file '{}': {}", path, e.what()));
  }
  nn::Rng unused_init(0);
  ConvAutoencoder<float> model(a, unused_init);
  model.load_from(file);
  return model;
}

void save_autoencoder(ConvAutoencoder<float>& model, const std::string& path) {
  nn::ModelFile file;
  model.save_to(file);
  file.write(path);
}

template class ConvAutoencoder<float>;
template class ConvAutoencoder<double>;

}  // namespace corrmp
