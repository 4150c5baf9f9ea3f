// Intervals clipped to metric ranges (metric_ranges.hpp).
#include "report/metric_ranges.hpp"

#include <algorithm>
#include <cmath>

namespace corrmp {

namespace {

double clipped(double value, const ValueRange& range) {
  return std::isnan(value) ? value : std::clamp(value, range.min, range.max);
}

}  // namespace

ValueRange difference_range(const ValueRange& range) {
  return {range.min - range.max, range.max - range.min};
}

IntervalBounds clip_interval(double low, double high, const ValueRange& range) {
  return {clipped(low, range), clipped(high, range)};
}

IntervalBounds metric_interval(const MetricDeclaration& metric, const MeanInterval& m) {
  return clip_interval(m.low, m.high, metric.range);
}

}  // namespace corrmp
