// Signal handling for clean interruption of runs.
#include "core/interrupt.hpp"

#include <signal.h>

#include <csignal>

namespace corrmp {

namespace {
volatile std::sig_atomic_t g_signal = 0;
void on_signal(int signal) { g_signal = signal; }
thread_local const std::atomic<bool>* t_stop = nullptr;
}  // namespace

StopWhen::StopWhen(const std::atomic<bool>& flag) : saved_(t_stop) { t_stop = &flag; }
StopWhen::~StopWhen() { t_stop = saved_; }

void install_interrupt_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  // A closed terminal stops cleanly as SIGTERM does, unless the process was started to ignore
  // it (nohup): then it stays ignored.
  struct sigaction hangup {};
  if (::sigaction(SIGHUP, nullptr, &hangup) == 0 && hangup.sa_handler != SIG_IGN) {
    std::signal(SIGHUP, on_signal);
  }
}

bool interrupt_requested() { return g_signal != 0 || (t_stop != nullptr && t_stop->load()); }

void check_interrupt() {
  if (interrupt_requested()) throw Interrupted();
}

}  // namespace corrmp
