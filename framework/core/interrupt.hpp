// Ctrl-C, SIGTERM and SIGHUP (a closed terminal): long loops call check_interrupt(), which
// throws Interrupted, so the run is marked 'interrupted' in the database cleanly.
#pragma once

#include <atomic>
#include <stdexcept>

namespace corrmp {

class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted by a signal") {}
};

void install_interrupt_handlers();
// True once a signal arrived, or, on a thread where a StopWhen lives, its flag is set.
bool interrupt_requested();
void check_interrupt();  // throws Interrupted when interrupt_requested()

// Work on a thread whose result nobody will wait for any more stops like an interrupted one:
// while a StopWhen lives on a thread, interrupt_requested() there is also true once `flag` is
// set (the networks trained beside a context extractor that failed, experiment/policy_fitting).
class StopWhen {
 public:
  explicit StopWhen(const std::atomic<bool>& flag);
  ~StopWhen();
  StopWhen(const StopWhen&) = delete;
  StopWhen& operator=(const StopWhen&) = delete;

 private:
  const std::atomic<bool>* saved_;
};

}  // namespace corrmp
