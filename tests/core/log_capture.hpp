// Test helper: collects what is logged through spdlog's default logger while
// it lives (the default logger is restored afterwards).
#pragma once

#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <memory>
#include <sstream>
#include <string>

namespace corrmp::testing {

class LogCapture {
 public:
  LogCapture() : previous_(spdlog::default_logger()) {
    auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(text_);
    sink->set_pattern("[%l] %v");
    auto logger = std::make_shared<spdlog::logger>("capture", sink);
    logger->set_level(spdlog::level::trace);
    spdlog::set_default_logger(logger);
  }
  ~LogCapture() { spdlog::set_default_logger(previous_); }
  LogCapture(const LogCapture&) = delete;
  LogCapture& operator=(const LogCapture&) = delete;

  // Everything logged so far, one "[level] message" line each.
  std::string text() const { return text_.str(); }
  // The lines logged at warning level.
  std::string warnings() const {
    std::istringstream lines(text_.str());
    std::string line, out;
    while (std::getline(lines, line)) {
      if (line.rfind("[warning]", 0) == 0) out += line + "\n";
    }
    return out;
  }

 private:
  std::ostringstream text_;
  std::shared_ptr<spdlog::logger> previous_;
};

}  // namespace corrmp::testing
