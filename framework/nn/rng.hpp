// Platform-independent random draws for weight initialisation.
//
// std::uniform_real_distribution is implementation-defined, so the same seed would give
// different weights with different standard libraries. These functions use only the raw
// output of std::mt19937_64, whose sequence the C++ standard fixes, so initial weights are
// bit-identical everywhere for the same seed:
//   u = (r >> 11) * 2^-53          (the top 53 bits of one 64-bit draw, u in [0, 1))
//   x = fma(hi - lo, u, lo)        (one rounding in double, then rounded to the scalar type)
#pragma once

#include <random>

#include "nn/tensor.hpp"

namespace corrmp::nn {

/// The random engine used for all initialisation in corrmp::nn.
using Rng = std::mt19937_64;

/// One draw from U[0, 1) built from the top 53 bits of a single engine output.
double uniform01(Rng& rng);

/// One draw from U[lo, hi).
double uniform(Rng& rng, double lo, double hi);

/// Fills data[0..n) with independent draws from U[-bound, bound), in memory order.
template <class S>
void fill_uniform(Rng& rng, double bound, S* data, Index n);

/// The PyTorch default bound for Linear / Conv weights and biases: kaiming_uniform with
/// a = sqrt(5) gives gain sqrt(2 / (1 + a^2)) = sqrt(1/3), std = gain / sqrt(fan_in) and bound
/// sqrt(3) * std = 1 / sqrt(fan_in); the bias uses the same bound.
double default_init_bound(Index fan_in);

}  // namespace corrmp::nn
