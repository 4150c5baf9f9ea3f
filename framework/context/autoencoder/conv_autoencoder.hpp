// The convolutional autoencoder whose latent vector is the context of the correction primitive
// (paper, Section III "Learning the Context"; architecture in autoencoder_params.hpp).
//
// With L convolutions of kernel k, padding p = (k - 1) / 2, strides s_i and filters f_i, an
// image x (C x H x H, values in [0, 1]) is encoded and decoded as
//   a_0 = x,  a_{i+1} = relu(conv_i(a_i))                  i = 0 .. L-1  (f_i channels)
//   z   = W_e flatten(a_L) + b_e                           (latent, no activation)
//   d_L = relu(unflatten(W_d z + b_d))                     (f_{L-1} x H_L x H_L)
//   d_i = relu(convT_i(d_{i+1}))  for i = L-1 .. 1,  x^ = sigmoid(convT_0(d_1))
// where convT_i mirrors conv_i: f_i -> f_{i-1} channels (C for i = 0), same k, s_i, p, and
// output_padding H_i - ((H_{i+1} - 1) s_i - 2 p + k) so that it restores the size H_i. With the
// paper's numbers: 3x64x64 -> 32x32x32 -> 32x32x32 -> 64x16x16 -> 64x16x16 -> 64x8x8 -> 4096 -> 8
// and back; 275 k parameters; about 54 M multiply-adds per image forward, 3 times that per
// training step (forward, weight gradients, input gradients).
//
// Loss (nn/mse_loss.hpp): L = (1 / (N D)) sum (x^ - x)^2 over a batch of N images of D values.
// Backward runs the chain in reverse with the layers' own backward passes (nn/conv2d.hpp,
// nn/conv_transpose2d.hpp, nn/linear.hpp), the ReLUs after the convolutions being applied inside
// the convolution layers (nn/relu_fusion.hpp); the output gradient through the sigmoid is
//   dL/d(pre-sigmoid) = (2 / (N D)) (x^ - x) x^ (1 - x^).
// train_step scales the whole gradient by `gradient_scale`, so data-parallel shards of one
// minibatch (autoencoder_trainer.hpp) each contribute (N_shard / N_batch) of their mean-loss
// gradient and their sum is the gradient of the minibatch mean.
//
// Batches follow nn/tensor.hpp: one image per row, flattened in C, H, W order. Activations live
// in nn::Buffer members, so a training step allocates nothing after the first step with the
// largest batch (apart from Eigen's GEMM workspace for the large 32x32 products where Eigen
// computes them, see nn/conv2d.hpp). Inference (encode, decode, reconstruct, reconstruction_mse)
// runs in chunks of kInferenceChunk images to bound memory. A ConvAutoencoder is copyable (the
// data-parallel trainer copies it into its worker replicas); it is not safe to use one object from
// two threads at once.
#pragma once

#include <cstdint>
#include <vector>

#include "context/autoencoder/autoencoder_params.hpp"
#include "nn/buffer.hpp"
#include "nn/conv2d.hpp"
#include "nn/conv_transpose2d.hpp"
#include "nn/linear.hpp"
#include "nn/model_file.hpp"
#include "nn/parameter.hpp"
#include "nn/rng.hpp"

namespace corrmp {

template <class S>
class ConvAutoencoder {
 public:
  using Mat = nn::Mat<S>;
  static constexpr nn::Index kInferenceChunk = 32;

  /// Validates the architecture (std::invalid_argument) and initialises the layers like
  /// PyTorch, in order: encoder convolutions, encoder Linear, decoder Linear, decoder
  /// transposed convolutions.
  ConvAutoencoder(const AutoencoderArchitecture& architecture, nn::Rng& rng);

  /// Forward, MSE against the input and backward on N images (N x image_values()). Accumulates
  /// gradient_scale * dL/dtheta into the parameter gradients (call nn::zero_grad between
  /// steps) and returns the batch's mean squared error L.
  S train_step(nn::ConstMatRef<S> images, S gradient_scale = S(1));

  /// Latents (N x latent_size) of N images.
  void encode(nn::ConstMatRef<S> images, nn::MatRef<S> latents);
  Mat encode(nn::ConstMatRef<S> images);
  /// Images (N x image_values(), in [0, 1]) decoded from N latents.
  void decode(nn::ConstMatRef<S> latents, nn::MatRef<S> images);
  Mat decode(nn::ConstMatRef<S> latents);
  /// decode(encode(images)).
  Mat reconstruct(nn::ConstMatRef<S> images);
  /// Mean squared reconstruction error over all N x image_values() entries (summed in double).
  double reconstruction_mse(nn::ConstMatRef<S> images);

  /// Transforms the weights of convolutions part, part + parts, ... (encoder's then decoder's)
  /// for their fast algorithms now (the layers do it when needed otherwise): the data-parallel
  /// trainer's workers share this work before the replicas run.
  void transform_weights(int part, int parts);
  /// For a data-parallel replica of `source` (a copy of it): its convolutions use `source`'s
  /// transformed weights whenever they are of the same weights (nn/conv2d.hpp). `source` must
  /// outlive this model and not transform other weights while this model runs.
  void share_weight_transforms(const ConvAutoencoder& source);

  /// Parameters in initialisation order, named "encoder.conv<i>.weight", "encoder.fc.bias",
  /// "decoder.fc.weight", "decoder.deconv<i>.bias" (deconv<i> mirrors conv<i>), ...
  std::vector<nn::Parameter<S>> parameters();
  std::int64_t parameter_count() const;
  const AutoencoderArchitecture& architecture() const { return architecture_; }
  nn::ImageShape image_shape() const;
  nn::Index image_values() const { return image_shape().size(); }
  nn::Index latent_size() const { return architecture_.latent_size; }

  /// Writes hyper "model" = "conv_autoencoder", the architecture ("autoencoder.image_size",
  /// ..., lists as "2,1,2,1,2") and the weights into `file`.
  void save_to(nn::ModelFile& file);
  /// Loads the weights; throws std::runtime_error naming the file when it holds another model
  /// or another architecture.
  void load_from(const nn::ModelFile& file);
  /// The architecture recorded in a file written by save_to (std::runtime_error otherwise).
  static AutoencoderArchitecture architecture_of(const nn::ModelFile& file);

 private:
  // Runs the encoder on x (N rows) up to the latent (stored in latent_).
  void forward_encoder(nn::ConstMatRef<S> x);
  // Runs the decoder on z (N rows) up to the reconstruction (stored in decoded_.back()).
  void forward_decoder(nn::ConstMatRef<S> z);
  // The next free gradient buffer shaped rows x cols (alternates between two buffers).
  nn::MatMap<S> next_gradient(nn::Index rows, nn::Index cols);

  AutoencoderArchitecture architecture_;
  std::vector<nn::Conv2d<S>> encoder_convs_;
  nn::Linear<S> encoder_fc_;
  nn::Linear<S> decoder_fc_;
  std::vector<nn::ConvTranspose2d<S>> decoder_convs_;  // decoder_convs_[i] mirrors conv i

  std::vector<nn::Buffer<S>> encoded_;  // a_1 .. a_L (post-ReLU)
  nn::Buffer<S> latent_;                // z
  nn::Buffer<S> decoder_fc_out_;        // d_L (post-ReLU)
  std::vector<nn::Buffer<S>> decoded_;  // decoded_[i]: output of convT_i (x^ for i = 0)
  nn::Buffer<S> gradients_[2];
  int next_gradient_ = 0;
};

/// Reads a model file written by ConvAutoencoder<float>::save_to and builds the model.
ConvAutoencoder<float> load_autoencoder(const std::string& path);
/// Writes the model to `path` (atomically, nn/model_file.hpp).
void save_autoencoder(ConvAutoencoder<float>& model, const std::string& path);

extern template class ConvAutoencoder<float>;
extern template class ConvAutoencoder<double>;

}  // namespace corrmp
