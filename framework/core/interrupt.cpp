// Signal handling for clean interruption of runs.
#include "core/interrupt.hpp"

#include <csignal>

namespace corrmp {

namespace {
volatile std::sig_atomic_t g_signal = 0;
void on_signal(int signal) { g_signal = signal; }
}  // namespace

void install_interrupt_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

bool interrupt_requested() { return g_signal != 0; }

void check_interrupt() {
  if (interrupt_requested()) throw Interrupted();
}

}  // namespace corrmp
