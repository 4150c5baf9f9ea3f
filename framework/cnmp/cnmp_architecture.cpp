// CNMP parameter counting and budget matching.
#include "cnmp/cnmp_architecture.hpp"

#include <cstdlib>

namespace corrmp {

namespace {
int64_t linear_params(int64_t in, int64_t out) { return in * out + out; }
}  // namespace

int64_t cnmp_parameter_count(const CnmpArchitecture& a) {
  const int64_t w = a.width;
  int64_t count = linear_params(a.d_x + a.d_y, w);
  for (int i = 1; i < a.encoder_layers; ++i) count += linear_params(w, w);
  const int64_t decoder_in = w + a.d_context + a.d_x;
  if (a.decoder_layers == 1) return count + linear_params(decoder_in, 2 * a.d_y);
  count += linear_params(decoder_in, w);
  for (int i = 2; i < a.decoder_layers; ++i) count += linear_params(w, w);
  return count + linear_params(w, 2 * a.d_y);
}

int width_for_parameter_budget(CnmpArchitecture architecture, int64_t budget) {
  int best = 1;
  int64_t best_gap = -1;
  for (int width = 1; width <= 4096; ++width) {
    architecture.width = width;
    const int64_t gap = std::llabs(cnmp_parameter_count(architecture) - budget);
    if (best_gap < 0 || gap < best_gap) {
      best_gap = gap;
      best = width;
    }
  }
  return best;
}

}  // namespace corrmp
