// The status of a recorded run, as the runs table spells it.
#pragma once

#include <string>

namespace corrmp {

// running: begun and not ended (or its process died before it could say so);
// completed: its trials and metrics are recorded; failed: it stopped with an error;
// interrupted: stopped by a signal, or found 'running' after its process ended.
enum class RunStatus { running, completed, failed, interrupted };

std::string to_string(RunStatus status);

// The status spelled `text`; throws std::invalid_argument naming it for any other text.
RunStatus run_status_from_string(const std::string& text);

}  // namespace corrmp
