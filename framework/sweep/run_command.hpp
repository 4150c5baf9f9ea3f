// Running a program without a shell and capturing what it prints: how the Slurm
// launcher calls sbatch. docs/slurm.md.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace corrmp {

struct CommandResult {
  int exit_code = 0;  // the program's exit status, or 128 + the signal that killed it
  std::string out;    // everything it wrote to stdout
  std::string err;    // everything it wrote to stderr
};

// The program could not be started: not on the PATH, or not executable.
class CommandNotFound : public std::runtime_error {
 public:
  explicit CommandNotFound(const std::string& what) : std::runtime_error(what) {}
};

// Runs argv[0], looked up in the PATH, with the arguments argv, stdin from /dev/null,
// and waits for it. Throws CommandNotFound when it cannot be executed and
// std::system_error when a pipe or the wait fails.
CommandResult run_command(const std::vector<std::string>& argv);

}  // namespace corrmp
