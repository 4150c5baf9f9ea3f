// The Wilson score interval (wilson_interval.hpp).
#include "stats/wilson_interval.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "stats/distributions.hpp"

namespace corrmp {

ProportionInterval wilson_interval(int successes, int trials, double confidence) {
  if (successes < 0 || successes > trials) {
    throw std::invalid_argument("Wilson interval: needs 0 <= successes <= trials");
  }
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument("confidence must lie in (0, 1)");
  }
  ProportionInterval p{successes, trials, 0.0, 0.0, 0.0};
  if (trials == 0) {
    p.rate = p.low = p.high = std::numeric_limits<double>::quiet_NaN();
    return p;
  }
  const double n = trials, rate = successes / n;
  const double z = normal_quantile(0.5 + confidence / 2), z2 = z * z;
  const double centre = (rate + z2 / (2 * n)) / (1 + z2 / n);
  const double half = z / (1 + z2 / n) * std::sqrt(rate * (1 - rate) / n + z2 / (4 * n * n));
  p.rate = rate;
  p.low = std::max(0.0, centre - half);
  p.high = std::min(1.0, centre + half);
  return p;
}

}  // namespace corrmp
