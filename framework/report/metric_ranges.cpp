// Metric value ranges and clipped intervals (metric_ranges.hpp).
#include "report/metric_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace corrmp {

namespace {

std::set<std::string> words_of(const std::string& name) {
  std::set<std::string> words;
  std::stringstream parts(name);
  std::string word;
  while (std::getline(parts, word, '_')) words.insert(word);
  return words;
}

double clipped(double value, const ValueRange& range) {
  return std::isnan(value) ? value : std::clamp(value, range.min, range.max);
}

}  // namespace

ValueRange metric_range(const std::string& metric) {
  const std::set<std::string> words = words_of(metric);
  if (words.count("rate")) return {0.0, 1.0};
  for (const char* word : {"error", "mse", "distance", "time", "seconds", "duration", "expected",
                           "failures", "demonstrations", "parameters"}) {
    if (words.count(word)) return {0.0, std::numeric_limits<double>::infinity()};
  }
  return {};
}

ValueRange difference_range(const ValueRange& range) {
  return {range.min - range.max, range.max - range.min};
}

IntervalBounds clip_interval(double low, double high, const ValueRange& range) {
  return {clipped(low, range), clipped(high, range)};
}

IntervalBounds metric_interval(const std::string& metric, const MeanInterval& m) {
  return clip_interval(m.low, m.high, metric_range(metric));
}

}  // namespace corrmp
