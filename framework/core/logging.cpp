// Logging set-up on spdlog.
#include "core/logging.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace corrmp {

namespace {
bool g_verbose = true;
}

void setup_logging(bool quiet) {
  g_verbose = !quiet;
  auto stderr_sink = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  stderr_sink->set_level(quiet ? spdlog::level::warn : spdlog::level::info);
  stderr_sink->set_pattern("%^[%H:%M:%S %l]%$ %v");
  auto logger = std::make_shared<spdlog::logger>("corrmp", stderr_sink);
  logger->set_level(spdlog::level::debug);
  spdlog::set_default_logger(logger);
}

void add_log_file(const std::string& path) {
  auto file_sink = std::make_shared<spdlog::sinks::basic_file_sink_mt>(path, true);
  file_sink->set_level(spdlog::level::debug);
  file_sink->set_pattern("[%Y-%m-%d %H:%M:%S.%e %l] %v");
  spdlog::default_logger()->sinks().push_back(file_sink);
  spdlog::default_logger()->flush_on(spdlog::level::info);
}

bool logging_verbose() { return g_verbose; }

}  // namespace corrmp
