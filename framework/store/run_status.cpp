// Run statuses as text (run_status.hpp).
#include "store/run_status.hpp"

#include <stdexcept>

namespace corrmp {

namespace {

constexpr RunStatus kStatuses[] = {RunStatus::running, RunStatus::completed, RunStatus::failed,
                                   RunStatus::interrupted};

}  // namespace

std::string to_string(RunStatus status) {
  switch (status) {
    case RunStatus::running:
      return "running";
    case RunStatus::completed:
      return "completed";
    case RunStatus::failed:
      return "failed";
    case RunStatus::interrupted:
      return "interrupted";
  }
  throw std::invalid_argument("a run status out of the enumeration");
}

RunStatus run_status_from_string(const std::string& text) {
  for (const RunStatus status : kStatuses) {
    if (to_string(status) == text) return status;
  }
  throw std::invalid_argument("'" + text +
                              "' is not a run status (running, completed, failed or interrupted)");
}

}  // namespace corrmp
