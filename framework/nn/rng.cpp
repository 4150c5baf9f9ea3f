// Platform-independent uniform draws (see nn/rng.hpp for the construction).
#include "nn/rng.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace corrmp::nn {

static_assert(Rng::min() == 0 && Rng::max() == UINT64_MAX,
              "the engine must emit full 64-bit words");

double uniform01(Rng& rng) {
  constexpr double kTwoPowMinus53 = 1.0 / 9007199254740992.0;
  return static_cast<double>(rng() >> 11) * kTwoPowMinus53;
}

// std::fma rounds once on every platform, so the result does not depend on whether the
// compiler would have contracted lo + (hi - lo) * u into a fused multiply-add.
double uniform(Rng& rng, double lo, double hi) { return std::fma(hi - lo, uniform01(rng), lo); }

template <class S>
void fill_uniform(Rng& rng, double bound, S* data, Index n) {
  for (Index i = 0; i < n; ++i) data[i] = static_cast<S>(uniform(rng, -bound, bound));
}

double default_init_bound(Index fan_in) {
  if (fan_in <= 0) throw std::invalid_argument("default_init_bound: fan_in must be positive");
  return 1.0 / std::sqrt(static_cast<double>(fan_in));
}

template void fill_uniform<float>(Rng&, double, float*, Index);
template void fill_uniform<double>(Rng&, double, double*, Index);

}  // namespace corrmp::nn
