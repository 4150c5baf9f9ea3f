// Progress bars and periodic progress log lines.
#include "core/progress.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "core/logging.hpp"

namespace corrmp {

namespace {

// The terminal line shared by every Progress: how many are active, and which one's bar
// occupies the current (unterminated) line.
std::mutex g_terminal_mutex;
int g_active = 0;
const void* g_bar_owner = nullptr;

int active_progress() {
  std::lock_guard<std::mutex> lock(g_terminal_mutex);
  return g_active;
}

// Ends the line of an open bar (of `owner`, or of any when null) so a log line starts afresh.
void close_bar(const void* owner) {
  std::lock_guard<std::mutex> lock(g_terminal_mutex);
  if (g_bar_owner != nullptr && (owner == nullptr || g_bar_owner == owner)) {
    std::fputs("\n", stderr);
    g_bar_owner = nullptr;
  }
}

}  // namespace

Progress::Progress(std::string label, int64_t total)
    : label_(std::move(label)),
      total_(std::max<int64_t>(total, 1)),
      terminal_(isatty(STDERR_FILENO) == 1 && logging_verbose()),
      start_(Clock::now()),
      last_report_(start_) {
  std::lock_guard<std::mutex> lock(g_terminal_mutex);
  ++g_active;
}

Progress::~Progress() {
  if (!finished_) {
    {
      std::lock_guard<std::mutex> lock(g_terminal_mutex);
      --g_active;
    }
    close_bar(this);
  }
}

double Progress::elapsed() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

std::string Progress::format_duration(double seconds) {
  const auto total = static_cast<int64_t>(seconds + 0.5);
  const int64_t h = total / 3600, m = (total / 60) % 60, s = total % 60;
  return h > 0 ? fmt::format("{}:{:02}:{:02}", h, m, s) : fmt::format("{}:{:02}", m, s);
}

void Progress::advance(int64_t steps, const std::string& status) {
  std::lock_guard<std::mutex> lock(mutex_);
  done_ = std::min(done_ + steps, total_);
  const auto now = Clock::now();
  const double since_report = std::chrono::duration<double>(now - last_report_).count();
  if (terminal_ && active_progress() == 1) {
    if (since_report >= 0.1 || done_ == total_) {
      last_report_ = now;
      draw(status);
    }
    return;
  }
  // Not a terminal, or other loops in progress: a log line at each tenth of the work, or
  // every 30 seconds.
  const int decile = static_cast<int>(10 * done_ / total_);
  if (decile > last_logged_decile_ || since_report >= 30.0) {
    last_logged_decile_ = decile;
    last_report_ = now;
    log_line(status);
  }
}

void Progress::log_line(const std::string& status) {
  if (terminal_) close_bar(nullptr);
  const double rate = done_ / std::max(elapsed(), 1e-9);
  spdlog::info("{}: {}/{} ({:.0f}%), {:.1f}/s, ETA {}{}", label_, done_, total_,
               100.0 * done_ / total_, rate, format_duration((total_ - done_) / rate),
               status.empty() ? "" : ", " + status);
}

void Progress::draw(const std::string& status) {
  constexpr int kWidth = 30;
  const double fraction = static_cast<double>(done_) / total_;
  const int filled = static_cast<int>(fraction * kWidth);
  const double rate = done_ / std::max(elapsed(), 1e-9);
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '.');
  std::lock_guard<std::mutex> lock(g_terminal_mutex);
  if (g_bar_owner != nullptr && g_bar_owner != this) std::fputs("\n", stderr);
  g_bar_owner = this;
  std::fprintf(stderr, "\r\033[K%s [%s] %3.0f%% %lld/%lld %.1f/s ETA %s %s", label_.c_str(),
               bar.c_str(), 100.0 * fraction, static_cast<long long>(done_),
               static_cast<long long>(total_), rate,
               format_duration((total_ - done_) / std::max(rate, 1e-9)).c_str(), status.c_str());
  std::fflush(stderr);
}

void Progress::finish(const std::string& status) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  finished_ = true;
  {
    std::lock_guard<std::mutex> terminal(g_terminal_mutex);
    --g_active;
  }
  close_bar(this);
  const double seconds = elapsed();
  spdlog::info("{}: {} in {} ({:.1f}/s){}", label_, done_, format_duration(seconds),
               done_ / std::max(seconds, 1e-9), status.empty() ? "" : ", " + status);
}

}  // namespace corrmp
