// Config field constraints: checks and their descriptions.
#include "core/config/field_rule.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace corrmp {

bool FieldRule::accepts(const std::string& value) const {
  return allowed.empty() || std::find(allowed.begin(), allowed.end(), value) != allowed.end();
}

std::string FieldRule::describe() const {
  if (!allowed.empty()) return "must be one of " + fmt::format("{}", fmt::join(allowed, ", "));
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  if (has_min && has_max) {
    return fmt::format("must be in {}{}, {}]", min_exclusive ? "(" : "[", min, max);
  }
  if (has_min) return fmt::format("must be {} {}", min_exclusive ? ">" : ">=", min);
  if (has_max) return fmt::format("must be <= {}", max);
  return "";
}

}  // namespace corrmp
