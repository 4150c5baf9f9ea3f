// Logging: spdlog to stderr (warnings only with --quiet) and, once a run
// directory exists, to its log.txt at every level.
#pragma once

#include <string>

namespace corrmp {

// Installs the default logger writing to stderr.
void setup_logging(bool quiet);
// Adds a file sink (the run's log.txt) to the default logger.
void add_log_file(const std::string& path);
// True when the stderr sink shows info messages (not --quiet).
bool logging_verbose();

}  // namespace corrmp
