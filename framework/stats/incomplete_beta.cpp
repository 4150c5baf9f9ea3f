// The regularized incomplete beta function (incomplete_beta.hpp).
#include "stats/incomplete_beta.hpp"

#include <cmath>
#include <stdexcept>

namespace corrmp {

namespace {

// The continued fraction 1 / (1 + d1 / (1 + d2 / (1 + ...))) of DLMF 8.17.22,
// whose value times x^a (1-x)^b / (a B(a, b)) is I_x(a, b). It converges fast
// for x < (a + 1) / (a + b + 2).
double beta_continued_fraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  constexpr double kEpsilon = 1e-16;
  constexpr int kMaxTerms = 10000;
  // Coefficient d_m of the fraction: odd and even terms differ.
  auto coefficient = [&](int m) {
    const int k = m / 2;
    if (m % 2 == 0) return k * (b - k) * x / ((a + 2 * k - 1) * (a + 2 * k));
    return -(a + k) * (a + b + k) * x / ((a + 2 * k) * (a + 2 * k + 1));
  };
  // Modified Lentz on F = 1 + d1 / (1 + d2 / (1 + ...)), guarding zero
  // denominators; the fraction wanted is 1 / F.
  double f = 1.0, c = 1.0, d = 0.0;
  for (int m = 1; m <= kMaxTerms; ++m) {
    const double numerator = coefficient(m);
    d = 1.0 + numerator * d;
    if (std::fabs(d) < kTiny) d = kTiny;
    d = 1.0 / d;
    c = 1.0 + numerator / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    const double step = c * d;
    f *= step;
    if (std::fabs(step - 1.0) < kEpsilon) return 1.0 / f;
  }
  throw std::runtime_error("incomplete beta: the continued fraction did not converge");
}

}  // namespace

double regularized_incomplete_beta(double a, double b, double x) {
  if (!(a > 0.0) || !(b > 0.0) || !(x >= 0.0 && x <= 1.0)) {
    throw std::invalid_argument("incomplete beta: needs a > 0, b > 0 and 0 <= x <= 1");
  }
  if (x == 0.0) return 0.0;
  if (x == 1.0) return 1.0;
  // log of x^a (1-x)^b / B(a, b)
  const double log_front =
      a * std::log(x) + b * std::log1p(-x) + std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b);
  // I_x(a, b) = 1 - I_{1-x}(b, a): evaluate the fraction where it converges.
  if (x < (a + 1.0) / (a + b + 2.0)) {
    return std::exp(log_front) * beta_continued_fraction(a, b, x) / a;
  }
  return 1.0 - std::exp(log_front) * beta_continued_fraction(b, a, 1.0 - x) / b;
}

}  // namespace corrmp
