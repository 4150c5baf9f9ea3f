// Constraints a config field declares: required or defaulted, numeric range,
// allowed strings, fixed list sizes. docs/architecture.md, "Configs" (out-of-range values are
// errors).
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace corrmp {

struct FieldRule {
  bool is_required = false;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  std::vector<std::string> allowed;  // empty: any string
  int list_size = -1;                // a list's exact number of items; -1: any

  FieldRule& required() {
    is_required = true;
    return *this;
  }
  FieldRule& at_least(double value) {
    min = value;
    min_exclusive = false;
    return *this;
  }
  FieldRule& above(double value) {
    min = value;
    min_exclusive = true;
    return *this;
  }
  FieldRule& at_most(double value) {
    max = value;
    return *this;
  }

  FieldRule& size_is(int items) {
    list_size = items;
    return *this;
  }

  bool accepts(double value) const {
    return (min_exclusive ? value > min : value >= min) && value <= max;
  }
  bool accepts(const std::string& value) const;
  // "must be >= 1", "must be in [0, 1]", "must be one of a, b"; "" when unconstrained.
  std::string describe() const;
};

inline FieldRule required() { return FieldRule{}.required(); }
inline FieldRule at_least(double value) { return FieldRule{}.at_least(value); }
inline FieldRule positive() { return FieldRule{}.above(0.0); }
inline FieldRule in_range(double lo, double hi) { return FieldRule{}.at_least(lo).at_most(hi); }
// A fixed-size list (a position, a size, a colour): exactly `items` entries.
inline FieldRule size_is(int items) { return FieldRule{}.size_is(items); }
inline FieldRule one_of(std::vector<std::string> allowed) {
  FieldRule rule;
  rule.allowed = std::move(allowed);
  return rule;
}

}  // namespace corrmp
