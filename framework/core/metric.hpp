// A measured value of a run together with what it means: its unit, the values it can take and
// which way is better. A metric is declared where it is measured and stored with its value, so
// that reports and intervals read its meaning instead of guessing it from its name
// (docs/architecture.md, "Database").
#pragma once

#include <limits>
#include <string>

namespace corrmp {

// The values a metric can take: a confidence interval around a mean of them is clipped to it.
struct ValueRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

inline bool operator==(const ValueRange& a, const ValueRange& b) {
  return a.min == b.min && a.max == b.max;
}

// Which way a metric is better; `neither` for a count or a setting such as a parameter count.
enum class Better { neither, higher, lower };

struct MetricDeclaration {
  std::string unit;  // "cm", "mm", "s"; "" for a rate, a count or a value in the data's own units
  ValueRange range;
  Better better = Better::neither;
  // The statistics of one measurement (a trajectory error's mean and max) share a `heading`, that
  // of the report column showing them together, and each names its `statistic` ("mean", "max").
  // Both empty for a metric shown on its own.
  std::string heading;
  std::string statistic;
};

inline bool operator==(const MetricDeclaration& a, const MetricDeclaration& b) {
  return a.unit == b.unit && a.range == b.range && a.better == b.better && a.heading == b.heading &&
         a.statistic == b.statistic;
}

struct Metric {
  std::string name;
  double value = 0.0;
  MetricDeclaration declaration{};  // nothing known unless the producer declares it
};

inline bool operator==(const Metric& a, const Metric& b) {
  return a.name == b.name && a.value == b.value && a.declaration == b.declaration;
}

// A fraction of trials or extractions, in [0, 1].
inline MetricDeclaration rate_metric(Better better) { return {"", {0.0, 1.0}, better, "", ""}; }

// A number of things (trials expected, failures, parameters), at least 0.
inline MetricDeclaration count_metric(Better better) {
  return {"", {0.0, std::numeric_limits<double>::infinity()}, better, "", ""};
}

// A distance, an error or a time in `unit`, at least 0, lower is better.
inline MetricDeclaration error_metric(const std::string& unit) {
  return {unit, {0.0, std::numeric_limits<double>::infinity()}, Better::lower, "", ""};
}

// Statistic `statistic` of an error shown in the report column `heading` (see heading above).
inline MetricDeclaration error_statistic(const std::string& unit, const std::string& heading,
                                         const std::string& statistic) {
  MetricDeclaration declaration = error_metric(unit);
  declaration.heading = heading;
  declaration.statistic = statistic;
  return declaration;
}

}  // namespace corrmp
