// The Student t and standard normal distributions: CDFs and quantiles, for
// confidence intervals across seeds (Student t with n - 1 degrees of freedom,
// or Welch's non-integer ones) and Wilson intervals (normal).
#pragma once

namespace corrmp {

// P(T <= t) for T ~ Student t with `dof` > 0 degrees of freedom (not
// necessarily an integer), via the regularized incomplete beta function.
double student_t_cdf(double t, double dof);

// The t with student_t_cdf(t, dof) = p, for p in (0, 1); e.g.
// student_t_quantile(0.975, 4) = 2.776. Throws std::invalid_argument outside.
double student_t_quantile(double p, double dof);

double normal_cdf(double z);
// The z with normal_cdf(z) = p, for p in (0, 1); normal_quantile(0.975) = 1.960.
double normal_quantile(double p);

}  // namespace corrmp
