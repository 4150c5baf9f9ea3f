// Safe sweep names and ids (sweep_names.hpp).
#include "sweep/sweep_names.hpp"

#include <fmt/format.h>

#include "core/parameter_error.hpp"

namespace corrmp {

std::string sweep_name_problem(const std::string& name) {
  if (is_safe_file_name(name) && name.size() <= kMaxSweepNameLength) return "";
  return fmt::format(
      "'{}' is not a valid sweep name (up to {} letters, digits, '_', '-', '.', not starting "
      "with '.')",
      name, kMaxSweepNameLength);
}

std::string sweep_id_problem(const std::string& id) {
  if (is_safe_file_name(id)) return "";
  return fmt::format(
      "'{}' is not a valid sweep id (up to 128 letters, digits, '_', '-', '.', not starting "
      "with '.')",
      id);
}

}  // namespace corrmp
