// Ctrl-C and SIGTERM: long loops call check_interrupt(), which throws
// Interrupted, so the run is marked 'interrupted' in the database cleanly.
#pragma once

#include <stdexcept>

namespace corrmp {

class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted by a signal") {}
};

void install_interrupt_handlers();
bool interrupt_requested();
void check_interrupt();  // throws Interrupted when a signal arrived

}  // namespace corrmp
