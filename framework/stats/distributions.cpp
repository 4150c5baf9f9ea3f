// Student t and normal CDFs and quantiles (distributions.hpp).
#include "stats/distributions.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

#include "stats/incomplete_beta.hpp"

namespace corrmp {

namespace {

// The x with cdf(x) = p for an increasing, continuous cdf symmetric about 0:
// bracket by doubling, then bisect until the bracket stops shrinking (full
// double precision; about 1100 halvings at most).
double invert_symmetric_cdf(const std::function<double(double)>& cdf, double p) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("quantile: p must lie in (0, 1)");
  if (p == 0.5) return 0.0;
  if (p < 0.5) return -invert_symmetric_cdf(cdf, 1.0 - p);
  double low = 0.0, high = 1.0;
  while (cdf(high) < p) {
    low = high;
    high *= 2.0;
    if (std::isinf(high)) return high;
  }
  for (;;) {
    const double middle = 0.5 * (low + high);
    if (middle <= low || middle >= high) return middle;
    (cdf(middle) < p ? low : high) = middle;
  }
}

}  // namespace

double student_t_cdf(double t, double dof) {
  if (!(dof > 0.0)) throw std::invalid_argument("Student t: degrees of freedom must be > 0");
  if (std::isnan(t)) return t;
  // P(|T| > |t|) = I_{dof / (dof + t^2)}(dof / 2, 1 / 2).
  const double tail = 0.5 * regularized_incomplete_beta(0.5 * dof, 0.5, dof / (dof + t * t));
  return t > 0.0 ? 1.0 - tail : tail;
}

double student_t_quantile(double p, double dof) {
  if (!(dof > 0.0)) throw std::invalid_argument("Student t: degrees of freedom must be > 0");
  return invert_symmetric_cdf([dof](double t) { return student_t_cdf(t, dof); }, p);
}

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

double normal_quantile(double p) { return invert_symmetric_cdf(normal_cdf, p); }

}  // namespace corrmp
