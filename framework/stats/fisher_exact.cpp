// Fisher's exact test, two-sided (fisher_exact.hpp).
#include "stats/fisher_exact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace corrmp {

namespace {

double log_choose(int n, int k) {
  return std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
}

}  // namespace

double fisher_exact_two_sided(int a, int b, int c, int d) {
  if (a < 0 || b < 0 || c < 0 || d < 0) {
    throw std::invalid_argument("Fisher's exact test: counts must not be negative");
  }
  const int row = a + b, column = a + c, total = a + b + c + d;
  // P(top-left cell = x) with the margins fixed.
  auto log_probability = [&](int x) {
    return log_choose(column, x) + log_choose(total - column, row - x) - log_choose(total, row);
  };
  const double observed = log_probability(a);
  constexpr double kRelativeTolerance = 1e-7;
  double p = 0.0;
  for (int x = std::max(0, row + column - total); x <= std::min(row, column); ++x) {
    const double lp = log_probability(x);
    if (lp <= observed + std::log1p(kRelativeTolerance)) p += std::exp(lp);
  }
  return std::min(1.0, p);
}

}  // namespace corrmp
