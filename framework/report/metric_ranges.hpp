// Confidence intervals clipped to the values a recorded metric can take (its declared range,
// core/metric.hpp), for every report that prints intervals (comparison, success plots, paper
// reproduction): a Student t interval around a mean of rates near 0 or 1, or of errors near 0,
// can reach values no run could give (a success rate of 1.08, an error of -0.3 cm). Only the
// bounds are clipped, never the mean.
#pragma once

#include "core/metric.hpp"
#include "stats/mean_interval.hpp"

namespace corrmp {

// The values of a difference of two values in `range`: [min - max, max - min]
// (a difference of rates lies in [-1, 1]).
ValueRange difference_range(const ValueRange& range);

struct IntervalBounds {
  double low = 0.0, high = 0.0;
};

// [low, high] clipped into `range`; a NaN bound (no interval) stays NaN.
IntervalBounds clip_interval(double low, double high, const ValueRange& range);

// The 95% interval of `m`, a mean of a metric across runs, clipped to the metric's declared range
// (the one form every report prints).
IntervalBounds metric_interval(const MetricDeclaration& metric, const MeanInterval& m);

}  // namespace corrmp
