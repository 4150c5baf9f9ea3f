// The values a recorded metric can take, and confidence intervals clipped to
// them, for every report that prints intervals (comparison, success plots,
// paper reproduction): a Student t interval around a mean of rates near 0 or
// 1, or of errors near 0, can reach values no run could give (a success rate
// of 1.08, an error of -0.3 cm). Only the bounds are clipped, never the mean.
#pragma once

#include <limits>
#include <string>

#include "stats/mean_interval.hpp"

namespace corrmp {

struct ValueRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

// By the metric's name, split into words at '_': a rate (the word "rate":
// task_success_rate, decision_match_rate_push, context_found_rate) lies in
// [0, 1]; an error, distance, time or count (the words error, mse, distance,
// time, seconds, duration, expected, failures, demonstrations, parameters) is
// at least 0; any other metric is unbounded.
ValueRange metric_range(const std::string& metric);

// The values of a difference of two values in `range`: [min - max, max - min]
// (a difference of rates lies in [-1, 1]).
ValueRange difference_range(const ValueRange& range);

struct IntervalBounds {
  double low = 0.0, high = 0.0;
};

// [low, high] clipped into `range`; a NaN bound (no interval) stays NaN.
IntervalBounds clip_interval(double low, double high, const ValueRange& range);

// The 95% interval of `m`, a mean of `metric` across runs, clipped to the metric's range
// (the one form every report prints).
IntervalBounds metric_interval(const std::string& metric, const MeanInterval& m);

}  // namespace corrmp
