// Progress of long loops (collection, training, evaluation): a bar with rate and
// ETA redrawn on stderr when stderr is a terminal, periodic log lines otherwise
// (so CI logs and log.txt show progress too). Silent on stderr with --quiet.
#pragma once

#include <chrono>
#include <cstdint>
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

  std::string label_;
  int64_t total_;
  int64_t done_ = 0;
  bool terminal_;
  bool finished_ = false;
  Clock::time_point start_;
  Clock::time_point last_report_;
  int last_logged_decile_ = 0;
};

}  // namespace corrmp
