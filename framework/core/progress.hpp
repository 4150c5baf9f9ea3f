// Progress of long loops (collection, training, evaluation): a bar with rate and
// ETA redrawn on stderr when stderr is a terminal, periodic log lines otherwise
// (so CI logs and log.txt show progress too). Silent on stderr with --quiet.
// Thread-safe: one Progress may be advanced from several threads, and several
// may run at once (segment networks trained concurrently); while more than one
// is active, none draws a bar: each logs a line per tenth of its work instead
// of fighting over one terminal line.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace corrmp {

class Progress {
 public:
  Progress(std::string label, int64_t total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Advances by `steps`; `status` (e.g. "val error 1.2 cm") is shown beside the bar.
  void advance(int64_t steps = 1, const std::string& status = "");
  // Ends the bar and logs the total time and rate once.
  void finish(const std::string& status = "");

  // Formats seconds as h:mm:ss or m:ss.
  static std::string format_duration(double seconds);

 private:
  using Clock = std::chrono::steady_clock;
  double elapsed() const;
  void draw(const std::string& status);
  void log_line(const std::string& status);

  std::string label_;
  int64_t total_;
  int64_t done_ = 0;
  bool terminal_;
  bool finished_ = false;
  Clock::time_point start_;
  Clock::time_point last_report_;
  int last_logged_decile_ = 0;
  std::mutex mutex_;  // guards the counts and times above
};

}  // namespace corrmp
