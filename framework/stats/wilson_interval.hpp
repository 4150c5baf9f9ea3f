// The Wilson score interval of a proportion: a group's success rate with its
// trials pooled across seeds (comparison and reproduction reports).
#pragma once

namespace corrmp {

struct ProportionInterval {
  int successes = 0, trials = 0;
  double rate = 0.0;  // NaN without trials
  double low = 0.0, high = 0.0;
};

// successes of trials (0 <= successes <= trials), `confidence` in (0, 1).
ProportionInterval wilson_interval(int successes, int trials, double confidence = 0.95);

}  // namespace corrmp
