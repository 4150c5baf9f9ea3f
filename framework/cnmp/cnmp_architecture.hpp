// Sizes of a Conditional Neural Movement Primitive (Seker et al., RSS 2019, as
// used in the paper's Section III-A "General Framework"), its parameter count,
// and the width that matches a parameter budget (the paper's monolithic
// baseline has as many parameters as the pre-, cor- and post-MP networks together).
#pragma once

#include <cstdint>

#include "core/config/field_rule.hpp"

namespace corrmp {

struct CnmpArchitecture {
  int d_x = 1;  // query input: time, plus optional task parameters
  int d_y = 1;  // output dimensions
  int d_context = 0;
  int encoder_layers = 3;  // Linear layers of the encoder (width -> latent of size width)
  int decoder_layers = 4;  // Linear layers of the decoder (last one -> 2 d_y)
  int width = 128;
  double min_std = 0.01;  // floor of the predicted standard deviation (normalised units)

  template <class Fields>
  void describe(Fields& f) {
    f("encoder_layers", encoder_layers, "Linear layers in the encoder", in_range(1, 16));
    f("decoder_layers", decoder_layers, "Linear layers in the decoder", in_range(1, 16));
    f("width", width, "hidden width of encoder and decoder", in_range(1, 4096));
    f("min_std", min_std, "floor of the predicted standard deviation (normalised units)",
      positive());
  }
};

// Number of trainable scalars of a CNMP with these sizes.
int64_t cnmp_parameter_count(const CnmpArchitecture& architecture);

// The width whose parameter count is closest to `budget` (other sizes fixed).
int width_for_parameter_budget(CnmpArchitecture architecture, int64_t budget);

}  // namespace corrmp
