// The regularized incomplete beta function I_x(a, b), from which the Student t
// distribution's CDF follows (intervals across seeds). Evaluated by its continued
// fraction (DLMF 8.17.22) with the modified Lentz method.
#pragma once

namespace corrmp {

// I_x(a, b) for a > 0, b > 0 and x in [0, 1]; throws std::invalid_argument
// outside that domain.
double regularized_incomplete_beta(double a, double b, double x);

}  // namespace corrmp
